// Small numerical tools the procedures share: error propagation through any smooth function, and a
// Levenberg-Marquardt solver for whitened residuals with the parameter covariance at the solution.
#pragma once

#include <functional>
#include <string>

#include <Eigen/Core>

namespace plumb::calibration {

using VectorFn = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

// Central-difference Jacobian of f at x; step_i = 1e-6 * max(|x_i|, typical_i).
Eigen::MatrixXd numeric_jacobian(const VectorFn& f, const Eigen::VectorXd& x, const Eigen::VectorXd& typical);

// First-order covariance of f(x) when x has covariance cov_x.
Eigen::MatrixXd propagate(const VectorFn& f, const Eigen::VectorXd& x, const Eigen::MatrixXd& cov_x,
                          const Eigen::VectorXd& typical);

struct LmOptions {
  int max_iterations = 200;
  double tolerance = 1e-12;         // relative decrease of the cost that counts as converged
  bool scale_by_residual_variance = false;  // covariance *= chi2 / dof (weights known only relatively)
  double min_relative_singular_value = 1e-10;  // below this the parameters are not identifiable
};

struct LmResult {
  Eigen::VectorXd x;
  Eigen::MatrixXd covariance;
  double chi2 = 0;                // sum of squared whitened residuals
  int dof = 0;
  int iterations = 0;
  bool converged = false;
  double relative_singular_value = 0;   // smallest / largest of the scaled Jacobian
  Eigen::VectorXd residuals;
};

// Minimises |r(x)|^2, r being whitened (unit variance) residuals. Throws CalibrationError with
// `what` when the Jacobian is rank deficient (parameters not identifiable from the data).
LmResult levenberg_marquardt(const VectorFn& residuals, const Eigen::VectorXd& x0, const Eigen::VectorXd& typical,
                             const std::string& what, const LmOptions& options = {});

// Lower-triangular L with positive diagonal such that L^T L = M (M symmetric positive definite).
Eigen::Matrix3d lower_factor(const Eigen::Matrix3d& M);

// Centre c and shape M of the ellipsoid (u - c)^T M (u - c) = radius^2 through the points, by the
// algebraic least-squares fit. Throws CalibrationError when the points do not determine one.
void fit_ellipsoid(const std::vector<Eigen::Vector3d>& points, double radius, Eigen::Vector3d& centre,
                   Eigen::Matrix3d& shape);

}  // namespace plumb::calibration
