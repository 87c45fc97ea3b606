// An independent strapdown integration for the simulator tests: it sees only the samples, the
// latitude and g, and shares no code with the simulators, so integrating an error-free IMU from the
// true initial state and landing on the truth shows the sensors and the truth agree.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "plumb/core/sample.hpp"

namespace plumb::sim::test {

struct NavState {
  Eigen::Quaterniond q;  // tool frame -> NED (C_b^n)
  Eigen::Vector3d v, p;
};

struct NavDerivative {
  Eigen::Vector4d dq;    // (w, x, y, z)
  Eigen::Vector3d dv, dp;
};

inline Eigen::Vector4d coeffs(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }
inline Eigen::Quaterniond quat(const Eigen::Vector4d& c) { return Eigen::Quaterniond(c[0], c[1], c[2], c[3]); }
inline Eigen::Quaterniond pure(const Eigen::Vector3d& w) { return Eigen::Quaterniond(0.0, w.x(), w.y(), w.z()); }

inline Eigen::Vector3d earth_rate_ned(double latitude_rad) {
  return 7.292115e-5 * Eigen::Vector3d(std::cos(latitude_rad), 0.0, -std::sin(latitude_rad));
}

// q' = q (0, w_ib)/2 - (0, w_in) q/2 with w_in = w_ie (the transport rate is below 1e-8 rad/s);
// v' = C_b^n f - 2 w_ie x v + g_n; p' = v.
inline NavDerivative nav_rates(const NavState& s, const Eigen::Vector3d& w_ib, const Eigen::Vector3d& f,
                               const Eigen::Vector3d& w_ie, const Eigen::Vector3d& g_n) {
  NavDerivative d;
  d.dq = 0.5 * (coeffs(s.q * pure(w_ib)) - coeffs(pure(w_ie) * s.q));
  d.dv = s.q.toRotationMatrix() * f - 2.0 * w_ie.cross(s.v) + g_n;
  d.dp = s.v;
  return d;
}

inline NavState advance(const NavState& s, const NavDerivative& d, double h) {
  return {quat(coeffs(s.q) + h * d.dq), s.v + h * d.dv, s.p + h * d.dp};
}

// Classical RK4 from sample k to k + 1 (step dt): the end values are the samples themselves, the
// midpoint value is the cubic through the four nearest samples (weights -1, 9, 9, -1 over 16), so
// every step has O(dt^5) local error from both the integrator and the interpolation. At the first
// and last interval (both still in the simulated runs: constant rates) the average is used. The
// quaternion is normalised after the step.
inline void strapdown_step(NavState& x, const std::vector<Sample>& s, std::size_t k, double dt,
                           const Eigen::Vector3d& w_ie, const Eigen::Vector3d& g_n) {
  const std::size_t n = s.size();
  Eigen::Vector3d w_mid = 0.5 * (s[k].w + s[k + 1].w), f_mid = 0.5 * (s[k].f + s[k + 1].f);
  if (k >= 1 && k + 2 < n) {
    w_mid = (9.0 * (s[k].w + s[k + 1].w) - (s[k - 1].w + s[k + 2].w)) / 16.0;
    f_mid = (9.0 * (s[k].f + s[k + 1].f) - (s[k - 1].f + s[k + 2].f)) / 16.0;
  }
  const NavDerivative k1 = nav_rates(x, s[k].w, s[k].f, w_ie, g_n);
  const NavDerivative k2 = nav_rates(advance(x, k1, dt / 2), w_mid, f_mid, w_ie, g_n);
  const NavDerivative k3 = nav_rates(advance(x, k2, dt / 2), w_mid, f_mid, w_ie, g_n);
  const NavDerivative k4 = nav_rates(advance(x, k3, dt), s[k + 1].w, s[k + 1].f, w_ie, g_n);
  x.q = quat(coeffs(x.q) + dt / 6.0 * (k1.dq + 2.0 * k2.dq + 2.0 * k3.dq + k4.dq)).normalized();
  x.v += dt / 6.0 * (k1.dv + 2.0 * k2.dv + 2.0 * k3.dv + k4.dv);
  x.p += dt / 6.0 * (k1.dp + 2.0 * k2.dp + 2.0 * k3.dp + k4.dp);
}

// The angle of the small rotation c_bn c_nb, in degrees; its skew part carries the angle without
// acos's loss.
inline double angle_between_deg(const Eigen::Matrix3d& c_bn, const Eigen::Matrix3d& c_nb) {
  const Eigen::Matrix3d d = c_bn * c_nb;
  const Eigen::Vector3d v(d(2, 1) - d(1, 2), d(0, 2) - d(2, 0), d(1, 0) - d(0, 1));
  return std::asin(std::min(1.0, 0.5 * v.norm())) * 180.0 / 3.14159265358979323846;
}

}  // namespace plumb::sim::test
