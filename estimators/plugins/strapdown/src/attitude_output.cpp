#include "plumb/strapdown/attitude_output.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "plumb/strapdown/rotation.hpp"

namespace plumb::strapdown {

Eigen::Matrix3d angle_jacobian(const Eigen::Matrix3d& c_bn) {
  // The estimate is (I + [phi x]) C(true), so the angle error is angles(exp([phi x]) C) - angles(C).
  // The step is small against any attitude error of interest and large against round-off.
  constexpr double kStep = 1e-6;
  Eigen::Matrix3d j;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[i] = kStep;
    const Angles plus = angles_of((quaternion_from_rotation_vector(e).toRotationMatrix() * c_bn).transpose());
    const Angles minus = angles_of((quaternion_from_rotation_vector(-e).toRotationMatrix() * c_bn).transpose());
    j(0, i) = (plus.inclination - minus.inclination) / (2 * kStep);
    j(1, i) = wrap_pi(plus.azimuth - minus.azimuth) / (2 * kStep);
    j(2, i) = wrap_pi(plus.toolface - minus.toolface) / (2 * kStep);
  }
  return j;
}

AttitudeWithSigma attitude_with_sigma(const Eigen::Matrix3d& c_bn, const Eigen::Matrix3d& p_att,
                                      double min_sin_inclination) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  AttitudeWithSigma out;
  const Angles a = angles_of(c_bn.transpose());
  out.inclination = a.inclination;
  out.azimuth = a.azimuth < 0 ? a.azimuth + kTwoPi : a.azimuth;
  out.toolface = a.toolface < 0 ? a.toolface + kTwoPi : a.toolface;
  if (out.azimuth >= kTwoPi) out.azimuth = 0;
  if (out.toolface >= kTwoPi) out.toolface = 0;
  const double sin_inc = std::sin(a.inclination);
  out.azimuth_valid = out.toolface_valid = sin_inc > min_sin_inclination;
  const Eigen::Matrix3d j = angle_jacobian(c_bn);
  const Eigen::Matrix3d cov = j * p_att * j.transpose();
  out.inclination_sd = std::sqrt(std::max(0.0, cov(0, 0)));
  out.azimuth_sd = std::sqrt(std::max(0.0, cov(1, 1)));
  out.toolface_sd = std::sqrt(std::max(0.0, cov(2, 2)));
  // Near the pole the azimuth and toolface sigma are huge and honest (flagged invalid); only a
  // non-finite one is replaced by 0 ("not estimated").
  for (double* sd : {&out.inclination_sd, &out.azimuth_sd, &out.toolface_sd}) {
    if (!std::isfinite(*sd)) *sd = 0;
  }
  return out;
}

ReferenceToolface reference_toolface(const Eigen::Matrix3d& c_bn, const Eigen::Matrix3d& p_att,
                                     const Eigen::Vector3d& ref_n, double min_sin_angle) {
  const auto toolface_of = [&ref_n](const Eigen::Matrix3d& c) {
    const Eigen::Vector3d r = c.transpose() * ref_n;
    return std::atan2(-r.y(), r.x());
  };
  ReferenceToolface out;
  const Eigen::Vector3d r = c_bn.transpose() * ref_n;
  out.valid = std::hypot(r.x(), r.y()) > min_sin_angle * r.norm();
  const double m = toolface_of(c_bn);
  out.toolface = m < 0 ? m + 2 * std::numbers::pi : m;
  if (out.toolface >= 2 * std::numbers::pi) out.toolface = 0;
  // The same central differences as angle_jacobian().
  constexpr double kStep = 1e-6;
  Eigen::RowVector3d j;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[i] = kStep;
    j[i] = wrap_pi(toolface_of(quaternion_from_rotation_vector(e).toRotationMatrix() * c_bn) -
                   toolface_of(quaternion_from_rotation_vector(-e).toRotationMatrix() * c_bn)) /
           (2 * kStep);
  }
  out.sd = std::sqrt(std::max(0.0, (j * p_att * j.transpose())(0, 0)));
  if (!std::isfinite(out.sd)) out.sd = 0;
  return out;
}

}  // namespace plumb::strapdown
