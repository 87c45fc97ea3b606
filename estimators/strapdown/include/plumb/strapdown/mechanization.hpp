// Strapdown mechanization in the collar's local-level NED frame (METHODS.md section 4):
// attitude quaternion by 4th-order Runge-Kutta, normalised after each step, with the rates
// interpolated across the step by the parabola through this reading, the previous one and the one
// before (linearly when there is no earlier reading). Gyros sampled as instantaneous values make a
// straight line between samples wrong by dt^2 w''/8: at 10 Hz, when a 30 rpm rotation starts over
// 5 s, linear interpolation puts the toolface 7e-4 rad (0.04 deg) off during the ramp, the parabola
// 1e-5 rad. The state is still advanced one step at a time as each reading arrives (no delay); velocity by 2nd order (Heun); position by 1st order (Euler),
// as the source prescribes. Each step uses its own dt, so uneven sampling needs nothing special.
//
// Position by 1st order: p_k = p_{k-1} + v_{k-1} dt differs from the trapezoid by v' dt^2 / 2 per
// step, and the sum of those telescopes to (v_end - v_start) dt / 2 over any stretch: at 10 Hz and
// 0.1 m/s at most 5 mm over a whole run. A higher order would gain nothing measurable here (it
// would matter only for a fast vehicle at a low rate).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace plumb::strapdown {

// One IMU reading with the bias estimates already removed.
struct ImuReading {
  double t = 0;
  Eigen::Vector3d f = Eigen::Vector3d::Zero();  // specific force, m/s^2, tool frame
  Eigen::Vector3d w = Eigen::Vector3d::Zero();  // w_ib, rad/s, tool frame
};

// The whole-value (nominal) navigation state.
struct NavState {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();  // rotation matrix C_b^n
  Eigen::Vector3d v = Eigen::Vector3d::Zero();            // NED, m/s
  Eigen::Vector3d p = Eigen::Vector3d::Zero();            // NED from the collar, m
  double s = 0;  // distance travelled along the tool axis since alignment, m (compared with depth)
};

// What the error-state filter needs of the steps between two of its epochs (integrals over time).
struct StepIntegrals {
  double dt = 0;
  Eigen::Matrix3d c_bn = Eigen::Matrix3d::Zero();   // integral of C_b^n
  Eigen::Vector3d f_n = Eigen::Vector3d::Zero();    // integral of C_b^n f
  Eigen::Vector3d axis_n = Eigen::Vector3d::Zero(); // integral of the tool axis C_b^n e_z
  Eigen::Vector3d axis_cross_v = Eigen::Vector3d::Zero();  // integral of axis x v
  void clear() { *this = StepIntegrals(); }
};

class Mechanization {
 public:
  // w_ie in the navigation frame, g > 0 (m/s^2).
  Mechanization(const Eigen::Vector3d& w_ie_n, double g);
  // Advances `state` from reading a to reading b (b.t > a.t), adding the step to `integrals`.
  // `before` (optional): the reading before a, for the parabolic rate interpolation.
  void step(NavState& state, const ImuReading& a, const ImuReading& b, StepIntegrals* integrals = nullptr,
            const ImuReading* before = nullptr) const;
  const Eigen::Vector3d& earth_rate() const { return w_ie_; }
  double gravity() const { return g_n_.z(); }
  void set_gravity(double g) { g_n_.z() = g; }

  // Largest rotation (rad) of one Runge-Kutta sub-step: the 4th-order truncation per sub-step is
  // (angle/2)^5 / 120 = 8e-11 rad at 0.05 rad, so fast rotary drilling at a low rate (120 rpm at
  // 10 Hz turns 1.26 rad per sample) is split into sub-steps instead of losing toolface.
  static constexpr double kMaxSubstepAngle = 0.05;

 private:
  Eigen::Vector4d attitude_rate(const Eigen::Vector4d& q, const Eigen::Vector3d& w) const;
  Eigen::Vector3d w_ie_;
  Eigen::Vector3d g_n_;
};

}  // namespace plumb::strapdown
