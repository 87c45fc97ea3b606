// The error-state Kalman filter of the navigator (closed loop: every estimated error is fed back
// into the whole-value state and the error state restarts at zero).
//
// Errors are "estimate minus truth":
//   phi (0-2):  attitude error in the navigation frame, C_b^n(est) = (I + [phi x]) C_b^n(true)
//   dv  (3-5):  velocity error, NED, m/s        dp (6-8): position error, NED, m
//   dbg (9-11): gyro bias error, tool frame, rad/s
//   dba (12-14): accelerometer bias error, tool frame, m/s^2
//   ds  (15):   error of the along-hole distance integrated from the velocity (the quantity a
//               measured depth observes; no function of the other 15 states gives a path length)
//   dg  (16):   error of the gravity the mechanization uses, m/s^2, a random constant: a given
//               value is rarely known to better than 1e-3 m/s^2 and one learnt from |f| at
//               alignment is off by the accelerometer bias along the vertical and the mean's
//               noise; with depth the filter would otherwise turn either into tilt
//   dr  (17-18): error of the accelerometers' offset from the tool axis (tool x, y; m): turning at w,
//               they feel the centripetal w x (w x r) on top of the axis' motion, 0.9 m/s^2 at 90
//               rpm and 1 cm, which a filter without it learns as an accelerometer bias while the
//               string turns and carries, wrong, into the next stop's tilt
//   dk  (19):   error of the gyro scale factor about the tool axis (dimensionless): a rotary string
//               turns the tool through 10^4-10^5 degrees between stops, so 50 ppm (a tactical
//               datasheet's figure) is degrees of toolface; without this state the filter's toolface
//               sigma ignores it and the stop after a rotary segment keeps the wrong toolface, a
//               confident one, by calling the accelerometers' disagreement a bias
//   dm  (20):   error of the magnetometers' bias along the tool axis (uT): steel in the drill string
//               magnetizes along the axis, a few tenths of a uT, which turns the magnetic azimuth by
//               m sin(I) sin(A) / Bh (half a degree in a horizontal well) the same way at every stop;
//               as white noise per stop it would be averaged away and the azimuth followed with a
//               small sigma. Observable as the axis turns between stops; random constant.
// Continuous dynamics (flat earth, earth.hpp), C = C_b^n, f_n = C f:
//   phi' = -w_ie x phi - C dbg - C e_z w_z dk + C n_g          dv' = -f_n x phi - 2 w_ie x dv - C dba + e_D dg - C L dr + C n_a
//   dp'  = dv        dbg' = n_bg        dba' = n_ba (random walks)
//   ds'  = (axis x v) . phi + axis . dv        (axis = C e_z, the tool axis in NED)       dg' = 0, dr' = 0, dk' = 0, dm' = 0
//   (L = centripetal_matrix(w): w x (w x r) = L r for r = (r_x, r_y, 0))
// Measurements are residuals r = h(estimate) - z = H dx + noise.
#pragma once

#include <array>

#include <Eigen/Core>
#include <Eigen/LU>

#include "plumb/strapdown/mechanization.hpp"
#include "plumb/strapdown/unseen_motion_noise.hpp"

namespace plumb::strapdown {

inline constexpr int kStates = 25;
using StateVector = Eigen::Matrix<double, kStates, 1>;
using StateMatrix = Eigen::Matrix<double, kStates, kStates>;

namespace index {
inline constexpr int kAtt = 0, kVel = 3, kPos = 6, kGyroBias = 9, kAccelBias = 12, kDistance = 15, kGravity = 16,
                     kLever = 17, kGyroLeak = 19, kGyroScale = 21, kMagAxial = 22, kGyroG = 23;
// kGyroLeak (x, y) and kGyroScale are, in this order, the gyro triad's response to a rate about the
// tool axis beyond that rate: what the x and y gyros read of it (their misalignment) and the z gyro's
// scale-factor error.
inline constexpr int kGyroSpin = kGyroLeak;
// kGyroG (2): the part of the x and y gyros' sensitivity to the lateral specific force that a turning
// tool rectifies: g_s (the same on both) and g_a (the cross terms' antisymmetric part), so that
// w_x reads g_s f_x - g_a f_y and w_y reads g_a f_x + g_s f_y more. Gravity turning through the
// sensor at every revolution makes them a steady drift of a rotary string's inclination or azimuth.
}

// Noise densities in SI units.
struct ProcessNoise {
  double gyro_arw = 0;         // rad/sqrt(s)
  double accel_vrw = 0;        // m/s/sqrt(s)
  double gyro_bias_walk = 0;   // rad/s/sqrt(s)
  double accel_bias_walk = 0;  // m/s^2/sqrt(s)
};

class ErrorStateFilter {
 public:
  void reset(const StateMatrix& p0) { p_ = p0; }
  // A state kept out of every update, as Schmidt's "consider" states are (-1: none): its estimate
  // and its variance stay, while its covariance with the others follows each update (the Joseph
  // form below holds for any gain, here the optimal one with that state's row set to zero). For a
  // parameter no motion of the run tells apart from the others, which an estimate would learn only
  // from the others' modelling errors (the string's magnetization: docs/navigator.md).
  void consider(int state) { considered_ = state; }
  const StateMatrix& covariance() const { return p_; }
  StateMatrix& covariance() { return p_; }

  // The continuous dynamics F over an epoch from the integrals the mechanization gathered (means
  // over the epoch stand in for the time-varying F).
  static StateMatrix dynamics(const StepIntegrals& integrals, const Eigen::Vector3d& w_ie);
  // Transition matrix over the epoch, I + F dt + (F dt)^2 / 2 with F = dynamics(), written block by
  // block (the same matrix; its zero blocks stay exactly zero, which sandwich() relies on).
  static StateMatrix transition(const StepIntegrals& integrals, const Eigen::Vector3d& w_ie);
  // The covariance predicted over a transition: phi p phi' plus the discrete process noise,
  // trapezoidal in time, (phi Q phi' + Q) / 2 with Q = diag(q) the white noises over dt; computed
  // as phi (p + Q/2) phi' + Q/2: one sandwich, not two.
  static StateMatrix predicted_covariance(const StateMatrix& phi, const StateMatrix& p, double dt,
                                          const ProcessNoise& noise);
  // phi m phi' for a transition() matrix (or the identity): its bias rows (9-14) are those of the
  // identity and most of its other 3 x 3 blocks are zero, so only the non-zero blocks take a product.
  static StateMatrix sandwich(const StateMatrix& phi, const StateMatrix& m);
  // predicted_covariance() in place, P exactly symmetric after it: for any phi whose rows other
  // than attitude, velocity, position and distance are the identity's, as transition()'s are.
  void predict(const StateMatrix& phi, double dt, const ProcessNoise& noise);

  // P H' over the states H touches (zero velocity: the velocity's three; lateral velocity:
  // attitude and velocity): a sum over H's non-zero columns only (the terms left out are exact
  // zeros).
  template <int M>
  Eigen::Matrix<double, kStates, M> p_ht(const Eigen::Matrix<double, M, kStates>& h) const;

  // One measurement: Joseph-form update, P kept symmetric. Returns the error estimate (to feed
  // back); `nis` (if given) receives the normalised innovation squared r' S^-1 r.
  // Defined in error_state_filter.cpp for M = 1, 2, 3: the 25-state products are compiled once,
  // not in every file that updates the filter (the work of a call is far above a call's cost).
  template <int M>
  StateVector update(const Eigen::Matrix<double, M, 1>& r, const Eigen::Matrix<double, M, kStates>& h,
                     const Eigen::Matrix<double, M, M>& noise, double* nis = nullptr);
  // The same with P H' as p_ht() gave it (for a caller that tested the innovation against it first;
  // P has not changed since).
  template <int M>
  StateVector update(const Eigen::Matrix<double, M, 1>& r, const Eigen::Matrix<double, M, kStates>& h,
                     const Eigen::Matrix<double, M, M>& noise, const Eigen::Matrix<double, kStates, M>& pht,
                     double* nis = nullptr);

  // After feeding dx back into the whole-value state the error state is zero again; its
  // covariance is unchanged to first order (the attitude reset Jacobian is I - [dphi x]/2 ~ I).
  void symmetrize() { p_ = 0.5 * (p_ + p_.transpose()).eval(); }

 private:
  // The states whose columns of h are not zero, in increasing order; returns how many.
  template <int M>
  static int touched_states(const Eigen::Matrix<double, M, kStates>& h, std::array<int, kStates>& touched);

  StateMatrix p_ = StateMatrix::Identity();
  int considered_ = -1;
};

// Process noise beyond the figures' added to a covariance (unseen_motion_noise.hpp).
void add_noise(StateMatrix& p, const UnseenMotionNoise& extra);

// Applies an error estimate to the whole-value state (and the bias estimates).
void feed_back(const StateVector& dx, NavState& state, Eigen::Vector3d& gyro_bias, Eigen::Vector3d& accel_bias,
               Eigen::Vector2d* lever = nullptr, Eigen::Vector3d* gyro_spin = nullptr, double* mag_axial = nullptr,
               Eigen::Vector2d* gyro_g = nullptr);

}  // namespace plumb::strapdown
