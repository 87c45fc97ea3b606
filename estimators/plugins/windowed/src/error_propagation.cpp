#include "plumb/windowed/error_propagation.hpp"

#include <cmath>

#include <Eigen/Dense>

#include "plumb/core/attitude.hpp"

namespace plumb::windowed {

Eigen::Vector3d propagate_attitude_sd(const AttitudeFunction& f, const Eigen::VectorXd& x, const Eigen::MatrixXd& cov) {
  const Eigen::Index m = x.size();
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(3, m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const double sd = std::sqrt(std::max(0.0, cov(i, i)));
    if (!(sd > 0)) continue;
    // A tenth of a sigma: small enough to be the local slope, large enough to stay above rounding.
    const double h = 0.1 * sd;
    Eigen::VectorXd up = x, down = x;
    up[i] += h;
    down[i] -= h;
    const Eigen::Vector3d fu = f(up), fd = f(down);
    for (int k = 0; k < 3; ++k) jacobian(k, i) = std::remainder(fu[k] - fd[k], 2 * kPi) / (2 * h);
  }
  const Eigen::Matrix3d out = jacobian * cov * jacobian.transpose();
  Eigen::Vector3d sd;
  for (int k = 0; k < 3; ++k) {
    const double v = std::sqrt(std::max(0.0, out(k, k)));
    sd[k] = std::isfinite(v) ? std::min(v, kPi) : kPi;
  }
  return sd;
}

Eigen::Vector3d propagate_attitude_sd_independent(const AttitudeFunction& f, const Eigen::VectorXd& x,
                                                 const Eigen::VectorXd& var) {
  return propagate_attitude_sd(f, x, Eigen::MatrixXd(var.asDiagonal()));
}

}  // namespace plumb::windowed
