// Strapdown mechanization in the collar's local-level NED frame (docs/methods.md section 4), in two
// rates, as inertial navigation systems do:
// - per reading (the minor step), only the motion relative to the tool frame at the last full
//   update (b0): the attitude increment and the velocity and position sums the step adds there;
// - at the filter's epochs (and whenever the state is asked for), the full update: attitude,
//   velocity (gravity, Coriolis) and position in the navigation frame.
// The earth's rotation is folded into the minor steps as a constant rotation of b0
// (C(t) = exp(-[w_ie x] t) C0 B(t) = C0 exp(-[w_b0 x] t) B(t), w_b0 = C0' w_ie, exact for a constant
// w_ie), so the accumulated attitude C~ = C0' C is exact at every reading and nothing of it is
// approximated at the lower rate.
//
// Attitude: each step's rotation vector by the 4th-order Magnus expansion, the rates at the two
// Gauss points of the step, phi = h (w1 + w2) / 2 + sqrt(3) h^2 / 12 (w1 x w2), its second term the
// coning correction; then composed as an exact quaternion product (the exponential by its series).
// For given rates the step is 4th order, as the source's Runge-Kutta (which it replaced, at the
// same accuracy or better: tests/unit/strapdown/mechanization_truth_test.cpp), and exact for a
// rotation about a fixed axis such as the toolface spin (where Runge-Kutta loses th^5 / 1920 per
// step). The rates are interpolated across the step by the parabola through this reading, the
// previous one and the one before (linearly when there is no earlier reading): gyros sampled as
// instantaneous values make a straight line between samples wrong by dt^2 w''/8; at 10 Hz, when a
// 30 rpm rotation starts over 5 s, linear interpolation puts the toolface 7e-4 rad (0.04 deg) off
// during the ramp, the parabola 1e-5 rad. That parabola looks back only (each reading is used as it
// arrives, without waiting for the next), so a rate that curves leaves 3rd-order residuals (a foot's
// swing). Large turns per step (120 rpm at 10 Hz: 1.26 rad) are split into sub-steps.
// Velocity: the specific force integrated by the trapezoid over each step in b0 (2nd order, the
// same sum as Heun's), gravity exactly, Coriolis over the epoch from the position change.
// Position and along-hole distance: 1st order (Euler), as the source prescribes. Each step uses its
// own dt, so uneven sampling needs nothing special.
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
  Eigen::Matrix<double, 3, 2> c_lever = Eigen::Matrix<double, 3, 2>::Zero();  // integral of C_b^n L(w)
  Eigen::Matrix3d spin_frame = Eigen::Matrix3d::Zero();  // integral of C_b^n times the rate about the tool axis
  Eigen::Matrix<double, 3, 2> c_gyro_g = Eigen::Matrix<double, 3, 2>::Zero();  // integral of C_b^n G(f) (gyro_g_matrix)
  // Variance of the velocity change the readings cannot resolve (m^2/s^2, across the tool axis):
  // the specific force's scatter from one reading to the next (vibration) integrated while the tool
  // turns within a reading's interval (unresolved_velocity_variance).
  double unresolved_dv2 = 0;
  void clear() { *this = StepIntegrals(); }
};

// Below this squared rate (0.01 rad/s) the centripetal acceleration of a point 1 cm off the axis is
// under 1e-6 m/s^2: not worth a product per reading.
inline constexpr double kTurningRate2 = 1e-4;

// A reading of the specific force is its value at one instant of the step (or its mean over the
// step): while the tool turns by theta within the step, vibration that changes from one reading
// to the next is integrated through an attitude the readings do not resolve, and the velocity
// change is uncertain by about (theta / sqrt(12)) |delta f across the axis| dt / sqrt(2) (the
// turn's offset from the step's middle, uniform; the scatter of two readings' difference is twice
// the vibration's). Negligible when the readings resolve both the turn and the vibration (at
// 400 Hz 0.03 rad per step); at 10 Hz a string turning at 120 rpm turns 1.3 rad per reading, and
// 0.45 g of vibration makes it centimetres per second per reading.
inline double unresolved_velocity_variance(double turn2, double dt, const Eigen::Vector3d& delta_f,
                                           const Eigen::Vector3d& axis) {
  const double along = axis.dot(delta_f);
  return (turn2 / 12.0) * dt * dt * 0.5 * (delta_f.squaredNorm() - along * along);
}

// The centripetal acceleration of a point r = (r_x, r_y, 0) off the tool axis, w x (w x r) =
// L(w) r: L's columns are w x (w x e_x) and w x (w x e_y).
// The gyro rate error of the rectifying g-sensitivity (g_s, g_a) is G(f) (g_s, g_a).
inline Eigen::Matrix<double, 3, 2> gyro_g_matrix(const Eigen::Vector3d& f) {
  Eigen::Matrix<double, 3, 2> m;
  m << f.x(), -f.y(), f.y(), f.x(), 0.0, 0.0;
  return m;
}

inline Eigen::Matrix<double, 3, 2> centripetal_matrix(const Eigen::Vector3d& w) {
  const double w2 = w.squaredNorm();
  Eigen::Matrix<double, 3, 2> l;
  l << w.x() * w.x() - w2, w.x() * w.y(), w.y() * w.x(), w.y() * w.y() - w2, w.z() * w.x(), w.z() * w.y();
  return l;
}

// A sensor that reports the mean over each sample interval sees a vector fixed in the navigation
// frame (gravity) turn under it by theta = |w| dt while it averages: the part across the rotation
// axis comes out shortened by sin(theta/2) / (theta/2), which is 3.7 % of g sin(I) at 90 rpm and
// 10 Hz, a lateral force the filter would have to call a tilt or a bias. This restores the value at
// the interval's middle from the mean (exact for a uniform rotation; the part along the axis and
// anything fixed in the tool frame, such as the bias or the centripetal term, must be taken out
// before). Below 1e-3 rad a turn shortens nothing measurable.
Eigen::Vector3d mean_to_instant(const Eigen::Vector3d& mean_f, const Eigen::Vector3d& w, double dt);
// Its inverse: the mean over the interval of a force whose value at the middle is instant_f.
Eigen::Vector3d instant_to_mean(const Eigen::Vector3d& instant_f, const Eigen::Vector3d& w, double dt);

class Mechanization {
 public:
  // w_ie in the navigation frame, g > 0 (m/s^2).
  Mechanization(const Eigen::Vector3d& w_ie_n, double g);

  // Starts the minor steps from `state` (the last full update, or the state after a correction).
  void begin(const NavState& state);
  // One minor step from reading a to reading b (b.t > a.t); `before` (optional): the reading
  // before a, for the parabolic rate interpolation (only its time and rate are read).
  void step(const ImuReading& a, const ImuReading& b, const ImuReading* before = nullptr);
  // A turn about the tool's axis at the last reading that its readings did not show (a clipped
  // gyro's, clipped_spin.hpp): the axis, and so the velocity and position, stay as they are.
  void turn_about_axis(double angle);
  // A change of velocity and position at the last reading that its readings did not show (a gap's
  // velocity across a drilling tool's axis, which is vibration: navigator.cpp), navigation frame.
  void shift(const Eigen::Vector3d& dv_n, const Eigen::Vector3d& dp_n);
  // The full update: the state at the last reading, without starting again.
  NavState state() const;
  // The full update, adding the steps since begin() to `integrals`. The caller begins again from the
  // state it settles on (after the filter's corrections).
  void finish(NavState& state, StepIntegrals* integrals = nullptr);
  // One reading's step with its full update (begin, step, finish): for tests and single steps.
  void step(NavState& state, const ImuReading& a, const ImuReading& b, StepIntegrals* integrals = nullptr,
            const ImuReading* before = nullptr);

  // The tool frame's attitude at the last reading (tool to navigation frame): between full updates
  // the filter's state holds the last full update's, a few degrees behind a turning tool.
  Eigen::Matrix3d tool_to_nav() const { return c0_ * c_; }
  // The earth rate in the tool frame at the last reading, C_n^b w_ie (what a still gyro reads).
  Eigen::Vector3d earth_rate_in_tool() const { return c_.transpose().lazyProduct(w_b0_); }
  const Eigen::Vector3d& earth_rate() const { return w_ie_; }
  double gravity() const { return g_n_.z(); }
  void set_gravity(double g) { g_n_.z() = g; }
  // Whether the filter models the accelerometers' offset from the tool axis (StepIntegrals::c_lever).
  void set_lever_model(bool on) { lever_model_ = on; }
  // A drilling tool turns about its own axis: gather unresolved_velocity_variance() across it.
  void set_unresolved_vibration(bool on) { unresolved_vibration_ = on; }

  // Largest rotation (rad) of one sub-step. The Magnus step is exact about a fixed axis; for a
  // turning axis its 5th-order term grows with the angle, so fast rotary drilling at a low rate
  // (120 rpm at 10 Hz turns 1.26 rad per sample) is split into sub-steps instead of losing toolface.
  // The exponential's series is exact to round-off below this angle.
  static constexpr double kMaxSubstepAngle = 0.05;

 private:
  Eigen::Vector3d w_ie_;
  Eigen::Vector3d g_n_;
  // At begin(): the state, and w_ie, v and g in the tool frame b0.
  NavState start_;
  Eigen::Matrix3d c0_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d w_b0_ = Eigen::Vector3d::Zero(), v_b0_ = Eigen::Vector3d::Zero(), g_b0_ = Eigen::Vector3d::Zero();
  // Since begin(), in b0: attitude C~ = C0' C (quaternion and matrix), time, sum of the specific force
  // (the velocity change less gravity and Coriolis), the first-order position sums, the distance,
  // and the filter's integrals (of C~, of the axis x the velocity).
  Eigen::Quaterniond b_ = Eigen::Quaterniond::Identity();
  Eigen::Matrix3d c_ = Eigen::Matrix3d::Identity();
  double tau_ = 0, tau_sum_ = 0;
  Eigen::Vector3d u_ = Eigen::Vector3d::Zero(), u_sum_ = Eigen::Vector3d::Zero();
  double s_sum_ = 0;
  Eigen::Matrix3d c_int_ = Eigen::Matrix3d::Zero();
  Eigen::Vector3d axis_cross_v_int_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d spin_int_ = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, 2> gyro_g_int_ = Eigen::Matrix<double, 3, 2>::Zero();
  Eigen::Matrix<double, 3, 2> lever_int_ = Eigen::Matrix<double, 3, 2>::Zero(), last_lever_ = Eigen::Matrix<double, 3, 2>::Zero();
  double unresolved_dv2_ = 0;
  bool lever_model_ = false, unresolved_vibration_ = false;
  // Of the last reading (valid after the first step since begin()): C~ f, and axis x velocity in b0.
  Eigen::Vector3d last_f_ = Eigen::Vector3d::Zero(), last_axis_cross_v_ = Eigen::Vector3d::Zero();
  // C~ G(f) of the last reading and that reading's f (the next step's first reading when it is the same).
  Eigen::Matrix<double, 3, 2> last_gyro_g_ = Eigen::Matrix<double, 3, 2>::Zero();
  Eigen::Vector3d last_raw_f_ = Eigen::Vector3d::Zero();
  bool stepped_ = false;
  // The earth's turn of b0 over the last step's dt (0: none yet since begin()).
  double earth_dt_ = 0;
  Eigen::Quaterniond earth_turn_ = Eigen::Quaterniond::Identity();
};

}  // namespace plumb::strapdown
