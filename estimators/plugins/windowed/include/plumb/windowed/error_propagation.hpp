// Standard deviations of the attitude angles an estimator computes from noisy inputs:
// first-order propagation J Sigma J^T through the estimator's own formulas at the estimate, with
// the Jacobian J by central differences. No small-angle form: the same function that produced the
// angles is differentiated, so the sigmas follow the actual attitude (and blow up near vertical,
// where azimuth and toolface are ill-conditioned).
#pragma once

#include <functional>

#include <Eigen/Core>

namespace plumb::windowed {

// Inputs to (inclination, azimuth, toolface), all in radians.
using AttitudeFunction = std::function<Eigen::Vector3d(const Eigen::VectorXd&)>;

// One-sigma of each output (radians) for inputs x with covariance cov. Differences of outputs are
// wrapped to (-pi, pi]; each step is a tenth of the input's own sigma (inputs with zero variance
// contribute nothing). Results are capped at pi: beyond that an angle is simply unknown.
Eigen::Vector3d propagate_attitude_sd(const AttitudeFunction& f, const Eigen::VectorXd& x, const Eigen::MatrixXd& cov);

// The same for independent inputs with the given variances.
Eigen::Vector3d propagate_attitude_sd_independent(const AttitudeFunction& f, const Eigen::VectorXd& x,
                                                 const Eigen::VectorXd& var);

}  // namespace plumb::windowed
