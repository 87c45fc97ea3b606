// The navigator's filter state: the whole-value navigation state and the sensor errors it estimates
// (gyro and accelerometer biases, the gyros' response to a spin about the tool axis and to the
// lateral specific force, the accelerometers' offset from the tool axis, the magnetometers' bias
// along it, gravity), the error-state filter over them with its
// process noise, and the mechanization that carries the state from one filter epoch to the next.
// Measurements come in through update(), which feeds the filter's correction back into the state.
#pragma once

#include <Eigen/Core>

#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/measurements.hpp"
#include "plumb/strapdown/mechanization.hpp"
#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/navigator_config.hpp"
#include "plumb/strapdown/unseen_motion.hpp"

namespace plumb::strapdown {

class FilterState {
 public:
  // Before alignment: nothing estimated, the process noise of the stated figures, gravity as given.
  void reset(const NavigatorConfig& config);
  // At alignment: the coarse attitude, gravity, the mechanization at the latitude; every error
  // estimate zero. A drilling tool has an axis to turn about and move along (the gyro scale factor,
  // the axial magnetometer bias, a rate of penetration); lever_model adds the accelerometers' offset.
  void start(const Eigen::Matrix3d& c_bn, double g, double latitude, bool drilling_tool, bool lever_model);
  void reset_covariance(const StateMatrix& p0) { kf_.reset(p0); }

  // A reading with the filter's estimates taken out: the biases, the gyros' response to the spin and,
  // turning, the centripetal acceleration of the accelerometers' offset from the tool axis and the
  // tangential one of a spin that changes (stick-slip), whose rate of change the reading before
  // (earlier, when there is one) gives.
  ImuReading corrected(const InputReading& in, const InputReading* earlier, bool samples_are_means,
                       double dt_nominal) const;
  // A made-up reading (its force the value at its instant, with the accelerometers' bias) as the
  // sensor would have read it, so that corrected() gives its force back: the lever arm's
  // centripetal and tangential terms put in (at 70 rpm 1 cm off the axis, 0.5 m/s^2 turning with
  // the tool: taken out of readings that never held it, 0.15 m across a 2 s gap) and, for means,
  // the mean over its interval.
  void as_read(InputReading& made_up, const InputReading* earlier, bool samples_are_means, double dt_nominal) const;
  // One minor step of the mechanization from reading prev to reading in, with prev2 (if any) the
  // reading before prev, each as corrected() gives it. A step's later reading is the next step's
  // earlier one, and the estimates change only when the filter updates them: each reading is
  // corrected once (the same numbers as correcting it again at every step it takes part in).
  void step(const InputReading& prev, const InputReading& in, const InputReading* prev2, bool samples_are_means,
            double dt_nominal);
  // A turn about the tool axis its readings did not show, after the last step (clipped_spin.hpp).
  void turn_about_axis(double angle) { mech_.turn_about_axis(angle); }
  // A change of velocity and position since the last step that the readings did not show.
  void shift_motion(const Eigen::Vector3d& dv_n, const Eigen::Vector3d& dp_n) { mech_.shift(dv_n, dp_n); }
  // A filter epoch: the mechanization's full update, then the filter's prediction to it with the
  // given process noise. Returns the transition, for the smoother.
  struct Prediction {
    StateMatrix phi;
    double dt = 0;
    ProcessNoise noise;  // the process noise the prediction used
    // Added beyond that noise: what the readings could not show, and the unresolved vibration of
    // a turning tool in its velocity.
    UnseenMotionNoise extra = {};
    // phi's coupling of the velocity to the attitude took gravity and the force along the axis
    // alone (a drilling tool that did not turn: filter_state.cpp).
    bool across_axis_force_left_out = false;
  };
  Prediction predict(const ProcessNoise& noise, const UnseenMotionNoise& unseen = {});
  // The minor steps go on from the (corrected) state.
  void begin_steps();
  template <int M>
  void update(const Measurement<M>& m) {
    apply(kf_.update(m.r, m.h, m.noise));
  }
  // P H' of a measurement, for a caller that weighs its innovation before the update, which then
  // takes it (the covariance unchanged in between).
  template <int M>
  Eigen::Matrix<double, kStates, M> p_ht(const Measurement<M>& m) const {
    return kf_.p_ht(m.h);
  }
  template <int M>
  void update(const Measurement<M>& m, const Eigen::Matrix<double, kStates, M>& pht) {
    apply(kf_.update(m.r, m.h, m.noise, pht));
  }
  void clear_correction() { correction_.setZero(); }

  const NavState& state() const { return x_; }
  const Eigen::Vector3d& gyro_bias() const { return bg_; }
  const Eigen::Vector3d& accel_bias() const { return ba_; }
  const Eigen::Vector3d& gyro_spin() const { return gyro_spin_; }
  const Eigen::Vector2d& gyro_g() const { return gyro_g_; }
  double mag_axial_bias() const { return mag_axial_; }
  double gravity() const { return g_; }
  const StateMatrix& covariance() const { return kf_.covariance(); }
  StateMatrix& covariance() { return kf_.covariance(); }
  const ProcessNoise& noise() const { return noise_; }
  ProcessNoise& noise() { return noise_; }
  const Mechanization& mechanization() const { return mech_; }
  const StateVector& correction() const { return correction_; }
  bool drilling_tool() const { return drilling_tool_; }
  bool lever_model() const { return lever_model_; }

 private:
  // The sensor errors the filter estimates, back to zero (biases, lever arm, spin response, ...).
  void clear_estimates();
  void apply(const StateVector& dx);
  // corrected() before the step from the mean over the interval to the value at its instant (which
  // depends on the nominal interval, and that changes at every reading).
  ImuReading without_estimates(const InputReading& in, const InputReading* earlier) const;
  // A reading without_estimates() gave, with what it was corrected from: the reading's time and
  // that of the reading before it (NaN for none). Estimates that change empty it.
  struct CorrectedReading {
    bool valid = false;
    double earlier_t = 0;
    ImuReading r;
    bool holds(const InputReading& in, const InputReading* earlier) const;
  };
  void forget_corrected() { last_a_.valid = last_b_.valid = false; }

  NavState x_;
  Eigen::Vector3d bg_ = Eigen::Vector3d::Zero(), ba_ = Eigen::Vector3d::Zero();
  Eigen::Vector2d lever_ = Eigen::Vector2d::Zero();  // accelerometers' offset from the tool axis (x, y), m
  // The gyros' response to a rate w about the tool axis beyond it: the x and y gyros read
  // gyro_spin_.x() w and gyro_spin_.y() w (misalignment), the z gyro (1 + gyro_spin_.z()) w.
  Eigen::Vector3d gyro_spin_ = Eigen::Vector3d::Zero();
  Eigen::Vector2d gyro_g_ = Eigen::Vector2d::Zero();  // (g_s, g_a): see index::kGyroG
  double mag_axial_ = 0;   // the magnetometers' bias along the tool axis, uT
  // Given, or |mean f| at alignment; corrected by the filter's gravity state from then on.
  double g_ = 9.80665;
  bool lever_model_ = false;
  bool drilling_tool_ = false;
  ErrorStateFilter kf_;
  ProcessNoise noise_;
  Mechanization mech_{Eigen::Vector3d::Zero(), 9.80665};
  StepIntegrals integrals_;
  StateVector correction_ = StateVector::Zero();  // fed back since the epoch began (the smoother's)
  CorrectedReading last_a_, last_b_;  // the last step's readings
};

}  // namespace plumb::strapdown
