// The earth as the navigator sees it: a flat local-level NED frame fixed at the hole's collar,
// turning with the earth (docs/conventions.md "Navigation").
//
// Why flat earth is enough at drilling speeds (numbers for a 1-hour run):
// - Transport rate w_en = v / R: at 0.1 m/s (drilling runs at 0.01-0.1 m/s) it is
//   0.1 / 6.37e6 = 1.6e-8 rad/s (3e-3 deg/h): 1/3 of a navigation-grade gyro's bias (1e-2 deg/h),
//   1/300 of a tactical one's, 1/4500 of the earth rate. Over an hour it tilts the frame by
//   5.6e-5 rad (0.003 deg), and the filter's stops re-level it anyway.
// - Frame curvature: the local vertical turns by d / R = 1.6e-5 rad (3.3 arc-seconds) per 100 m of
//   horizontal offset from the collar; holes here are shorter than 1 km (1.6e-4 rad).
// - Gravity with depth: in free air |dg/dz| = 2g/R = 3.1e-6 s^-2, i.e. 3.1e-4 m/s^2 per 100 m;
//   inside rock (Bouguer slab, 2670 kg/m^3) it is 3.1e-6 - 4 pi G rho = 0.85e-6 s^-2, 8.5e-5 m/s^2
//   per 100 m. It is vertical, so it tilts nothing; it acts as a slowly changing vertical
//   accelerometer bias, which the filter's accelerometer-bias states follow at every stop.
// - Coriolis 2 w_ie x v at 0.1 m/s is 1.5e-5 m/s^2 (1.5 ug): kept, it costs nothing.
// So the mechanization keeps the earth rate and Coriolis and drops the transport rate, the frame
// curvature and gravity's change with position. Latitude is a parameter, not a state.
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace plumb::strapdown {

inline constexpr double kEarthRate = 7.292115e-5;   // rad/s (WGS-84)
inline constexpr double kSecondsPerHour = 3600.0;

// w_ie in the local-level NED frame at latitude L (rad), rotated by `frame_azimuth` (rad): the
// navigation frame's north may be magnetic (or the user's reference) instead of true north; true
// north then lies at azimuth -frame_azimuth in it (frame_azimuth = declination for a magnetic
// frame whose declination is known; 0 for a true-north frame).
inline Eigen::Vector3d earth_rate_ned(double latitude_rad, double true_north_azimuth_in_frame = 0.0) {
  const double h = kEarthRate * std::cos(latitude_rad);
  return {h * std::cos(true_north_azimuth_in_frame), h * std::sin(true_north_azimuth_in_frame),
          -kEarthRate * std::sin(latitude_rad)};
}

inline Eigen::Vector3d gravity_ned(double g) { return {0.0, 0.0, g}; }

}  // namespace plumb::strapdown
