// Rotation helpers of the navigator. The attitude is kept as the unit quaternion q whose rotation
// matrix is C_b^n (tool to navigation frame); docs/conventions.md's C_n^b is its transpose.
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace plumb::strapdown {

inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// The quaternion of a rotation vector (exact for any angle).
inline Eigen::Quaterniond quaternion_from_rotation_vector(const Eigen::Vector3d& r) {
  const double angle = r.norm();
  if (angle < 1e-12) return Eigen::Quaterniond(1.0, 0.5 * r.x(), 0.5 * r.y(), 0.5 * r.z()).normalized();
  const Eigen::Vector3d axis = r / angle;
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
}

// Inclination, azimuth and gravity toolface (rad) of C_n^b = R3(T) R2(I) R3(A). The third column of
// C_n^b is G/g = (-sinI cosT, sinI sinT, cosI); its third row is the tool axis in NED,
// (sinI cosA, sinI sinA, cosI). Both stay exact at any attitude; A and T lose meaning only as sinI -> 0.
struct Angles {
  double inclination = 0, azimuth = 0, toolface = 0;
};

inline Angles angles_of(const Eigen::Matrix3d& c_nb) {
  Angles a;
  a.inclination = std::atan2(std::hypot(c_nb(0, 2), c_nb(1, 2)), c_nb(2, 2));
  a.toolface = std::atan2(c_nb(1, 2), -c_nb(0, 2));
  a.azimuth = std::atan2(c_nb(2, 1), c_nb(2, 0));
  return a;
}

// Angle difference wrapped to (-pi, pi].
inline double wrap_pi(double a) {
  a = std::remainder(a, 2.0 * 3.14159265358979323846);
  return a;
}

}  // namespace plumb::strapdown
