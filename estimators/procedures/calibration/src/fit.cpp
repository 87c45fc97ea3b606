#include "plumb/calibration/fit.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "plumb/calibration/types.hpp"

namespace plumb::calibration {

Eigen::MatrixXd numeric_jacobian(const VectorFn& f, const Eigen::VectorXd& x, const Eigen::VectorXd& typical) {
  const Eigen::VectorXd f0 = f(x);
  Eigen::MatrixXd J(f0.size(), x.size());
  Eigen::VectorXd xp = x, xm = x;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const double h = 1e-6 * std::max(std::abs(x[i]), typical[i]);
    xp[i] = x[i] + h;
    xm[i] = x[i] - h;
    J.col(i) = (f(xp) - f(xm)) / (2 * h);
    xp[i] = xm[i] = x[i];
  }
  return J;
}

Eigen::MatrixXd propagate(const VectorFn& f, const Eigen::VectorXd& x, const Eigen::MatrixXd& cov_x,
                          const Eigen::VectorXd& typical) {
  const Eigen::MatrixXd J = numeric_jacobian(f, x, typical);
  return J * cov_x * J.transpose();
}

LmResult levenberg_marquardt(const VectorFn& residuals, const Eigen::VectorXd& x0, const Eigen::VectorXd& typical,
                             const std::string& what, const LmOptions& options) {
  LmResult out;
  Eigen::VectorXd x = x0;
  Eigen::VectorXd r = residuals(x);
  double cost = r.squaredNorm();
  double lambda = 1e-3;
  const auto n = x.size();
  for (int it = 0; it < options.max_iterations; ++it) {
    out.iterations = it + 1;
    const Eigen::MatrixXd J = numeric_jacobian(residuals, x, typical);
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 30 && !improved; ++tries) {
      Eigen::MatrixXd A = JtJ;
      A.diagonal() += lambda * JtJ.diagonal().cwiseMax(1e-300);
      const Eigen::VectorXd step = A.ldlt().solve(-g);
      if (!step.allFinite()) {
        lambda *= 10;
        continue;
      }
      const Eigen::VectorXd x_new = x + step;
      const Eigen::VectorXd r_new = residuals(x_new);
      const double c_new = r_new.squaredNorm();
      if (std::isfinite(c_new) && c_new <= cost) {
        const double decrease = cost - c_new;
        x = x_new;
        r = r_new;
        lambda = std::max(lambda / 10, 1e-12);
        improved = true;
        if (decrease <= options.tolerance * std::max(cost, 1e-300) + 1e-300) out.converged = true;
        cost = c_new;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) {
      out.converged = true;  // no step lowers the cost: at a minimum to working precision
      break;
    }
    if (out.converged) break;
  }

  // Identifiability and covariance at the solution, from the column-scaled Jacobian.
  const Eigen::MatrixXd J = numeric_jacobian(residuals, x, typical);
  Eigen::VectorXd scale(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double c = J.col(i).norm();
    scale[i] = c > 0 ? 1 / c : 1;
  }
  const Eigen::MatrixXd Js = J * scale.asDiagonal();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const auto& sv = svd.singularValues();
  out.relative_singular_value = sv.size() > 0 && sv[0] > 0 ? sv[sv.size() - 1] / sv[0] : 0;
  if (J.rows() < n || out.relative_singular_value < options.min_relative_singular_value)
    throw CalibrationError(what);
  Eigen::MatrixXd inv_s = Eigen::MatrixXd::Zero(n, n);
  inv_s.diagonal() = sv.cwiseInverse().cwiseAbs2();
  const Eigen::MatrixXd cov_s = svd.matrixV() * inv_s * svd.matrixV().transpose();
  out.covariance = scale.asDiagonal() * cov_s * scale.asDiagonal();
  out.x = x;
  out.residuals = r;
  out.chi2 = cost;
  out.dof = static_cast<int>(J.rows() - n);
  if (options.scale_by_residual_variance && out.dof > 0) out.covariance *= out.chi2 / out.dof;
  return out;
}

Eigen::Matrix3d lower_factor(const Eigen::Matrix3d& M) {
  // Reverse the index order, take the ordinary Cholesky factor, reverse back.
  Eigen::Matrix3d P = Eigen::Matrix3d::Zero();
  P(0, 2) = P(1, 1) = P(2, 0) = 1;
  Eigen::LLT<Eigen::Matrix3d> llt(P * M * P);
  if (llt.info() != Eigen::Success) throw CalibrationError("shape matrix is not positive definite");
  const Eigen::Matrix3d L = llt.matrixL();
  return P * L.transpose() * P;
}

void fit_ellipsoid(const std::vector<Eigen::Vector3d>& points, double radius, Eigen::Vector3d& centre,
                   Eigen::Matrix3d& shape) {
  // u^T Q u + p^T u = 1 (scaled), Q symmetric: 9 unknowns, linear least squares.
  const auto n = static_cast<Eigen::Index>(points.size());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(n);
  double spread = 0;
  for (const auto& p : points) spread = std::max(spread, (p - mean).norm());
  if (!(spread > 0)) throw CalibrationError("all positions read the same: they do not determine an ellipsoid");
  Eigen::MatrixXd H(n, 9);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d u = (points[static_cast<std::size_t>(i)] - mean) / spread;
    H.row(i) << u.x() * u.x(), u.y() * u.y(), u.z() * u.z(), 2 * u.x() * u.y(), 2 * u.x() * u.z(), 2 * u.y() * u.z(),
        u.x(), u.y(), u.z();
  }
  const Eigen::VectorXd k = H.colPivHouseholderQr().solve(Eigen::VectorXd::Ones(n));
  Eigen::Matrix3d Q;
  Q << k[0], k[3], k[4], k[3], k[1], k[5], k[4], k[5], k[2];
  const Eigen::Vector3d p = k.tail<3>();
  // (u - c)^T Q (u - c) = 1 + c^T Q c with c = -Q^-1 p / 2.
  const Eigen::Vector3d c = -0.5 * Q.ldlt().solve(p);
  const double rhs = 1 + c.dot(Q * c);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(Q / rhs);
  if (!k.allFinite() || !(rhs > 0) || es.eigenvalues().minCoeff() <= 0)
    throw CalibrationError("positions do not determine an ellipsoid (too few or not spread over all directions)");
  centre = mean + spread * c;
  shape = (Q / rhs) * (radius * radius) / (spread * spread);
}

}  // namespace plumb::calibration
