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

// The quaternion of a rotation vector, exact for any angle: below 0.1 rad by the series of
// cos(x/2) and sin(x/2)/x to x^8 (the next terms are below 3e-20), which needs no square root, no
// trigonometry and (the coefficients as reciprocals) no division; the mechanization and the
// stillness watch take one per reading.
inline Eigen::Quaterniond quaternion_from_rotation_vector(const Eigen::Vector3d& r) {
  const double t2 = r.squaredNorm();
  double c = 0, s = 0;  // cos(|r|/2), sin(|r|/2)/|r|
  if (t2 < 1e-2) {
    c = 1.0 - t2 * (1.0 / 8.0) * (1.0 - t2 * (1.0 / 48.0) * (1.0 - t2 * (1.0 / 120.0) * (1.0 - t2 * (1.0 / 224.0))));
    s = 0.5 * (1.0 - t2 * (1.0 / 24.0) * (1.0 - t2 * (1.0 / 80.0) * (1.0 - t2 * (1.0 / 168.0) * (1.0 - t2 * (1.0 / 288.0)))));
  } else {
    const double x = std::sqrt(t2);
    c = std::cos(0.5 * x);
    s = std::sin(0.5 * x) / x;
  }
  return Eigen::Quaterniond(c, s * r.x(), s * r.y(), s * r.z());
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
