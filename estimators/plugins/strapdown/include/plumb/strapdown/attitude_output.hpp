// Inclination, azimuth and gravity toolface of the navigator's attitude, with standard deviations
// propagated from the filter's attitude-error covariance through the actual Jacobian of (I, A, T)
// at the actual attitude: no small-angle form, so the azimuth and toolface sigma grow
// without bound as sinI -> 0 (vertical, or hanging upside down at I = 180 deg).
#pragma once

#include <Eigen/Core>

namespace plumb::strapdown {

struct AttitudeWithSigma {
  double inclination = 0, azimuth = 0, toolface = 0;           // rad; azimuth, toolface in [0, 2pi)
  double inclination_sd = 0, azimuth_sd = 0, toolface_sd = 0;  // rad
  bool azimuth_valid = false, toolface_valid = false;
};

// c_bn: C_b^n; p_att: covariance of the attitude error phi (navigation frame);
// min_sin_inclination: below it azimuth and toolface are flagged invalid.
AttitudeWithSigma attitude_with_sigma(const Eigen::Matrix3d& c_bn, const Eigen::Matrix3d& p_att,
                                      double min_sin_inclination);

// d(I, A, T)/d(phi) at C_b^n, by central differences of the exact angle formulas.
Eigen::Matrix3d angle_jacobian(const Eigen::Matrix3d& c_bn);

// The toolface from a direction fixed in the navigation frame, ref_n: atan2(-r_y, r_x) with
// r = C_n^b ref_n, the angle from the direction's part across the tool axis to the tool x axis.
// For the field's direction it is the magnetic toolface (docs/conventions.md), for north the gyro
// toolface: near vertical, where the gravity toolface and the azimuth are weakly defined (their
// sigma grows as 1/sin I), these stay defined (M = A + T at I = 0), as drilling tools steer by.
// Not valid where ref_n lies along the tool axis.
struct ReferenceToolface {
  double toolface = 0, sd = 0;  // rad; toolface in [0, 2pi)
  bool valid = false;
};
ReferenceToolface reference_toolface(const Eigen::Matrix3d& c_bn, const Eigen::Matrix3d& p_att,
                                     const Eigen::Vector3d& ref_n, double min_sin_angle);

}  // namespace plumb::strapdown
