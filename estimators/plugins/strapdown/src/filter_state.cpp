#include "plumb/strapdown/filter_state.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "plumb/strapdown/earth.hpp"

namespace plumb::strapdown {

using namespace index;

namespace {

// A drilling tool turning slower than this about its axis is not turning (about 2 rpm).
constexpr double kTurningRadPerS = 0.2;

// Over an epoch in which a drilling tool does not turn about its axis (sliding, or still), the force
// across the axis is gravity's and the vibration's of the bit at work. The vibration's velocity is
// the tool's own, in its frame whatever the attitude: the lateral-velocity update's attitude column
// leaves it out (measurements.cpp), so the velocity's dependence on the attitude must leave it out
// too, or the updates read the attitude off the vibration (an outside noisier-MEMS run sliding at
// one toolface: azimuth sigma 0.64 -> 0.37 deg over 15 minutes while the error stayed at 1 deg).
// A turning tool keeps the whole force: read at 10 Hz, what its readings do not resolve of the turn
// lies across the axis, and the attitude does turn that (an outside tactical rotary run at 10 Hz:
// azimuth 0.23 -> 0.53 deg off without it).
// Returns whether it did. (The axial-acceleration update, which reads the velocity's change through
// that coupling, takes the same part of it: stop_updates.cpp.)
bool keep_gravity_and_axial_force(StepIntegrals& in, double g) {
  // (Squared norms: this runs at every epoch.)
  const double turned = kTurningRadPerS * in.dt, axis2 = in.axis_n.squaredNorm();
  if (!(in.dt > 0) || !(axis2 > 0) || in.spin_frame.col(2).squaredNorm() >= turned * turned) return false;
  const Eigen::Vector3d rest(0.0, 0.0, -g * in.dt);
  in.f_n = rest + in.axis_n * (in.axis_n.dot(in.f_n - rest) / axis2);
  return true;
}

}  // namespace

void FilterState::reset(const NavigatorConfig& config) {
  g_ = config.gravity.value_or(9.80665);
  x_ = NavState();
  clear_estimates();
  lever_model_ = false;
  kf_ = ErrorStateFilter();
  if (!config.mag_axial_bias_learnt) kf_.consider(kMagAxial);
  noise_.gyro_arw = config.gyro_arw;
  noise_.accel_vrw = config.accel_vrw;
  noise_.gyro_bias_walk = config.gyro_bias_instability / std::sqrt(config.bias_time_s);
  noise_.accel_bias_walk = config.accel_bias_instability / std::sqrt(config.bias_time_s);
  integrals_.clear();
  correction_.setZero();
  forget_corrected();
}

void FilterState::start(const Eigen::Matrix3d& c_bn, double g, double latitude, bool drilling_tool,
                        bool lever_model) {
  g_ = g;
  // The earth rate's horizontal part is taken along the frame's north. That is exact in a true
  // frame (gyrocompass, or declination given); in a magnetic frame without a declination, or a
  // relative one, it errs by the horizontal earth rate times sin(declination): 0.9 deg/h per 5 deg
  // of declination at 45 deg latitude, a gyro-bias-like error the zero-rate updates absorb.
  mech_ = Mechanization(earth_rate_ned(latitude, 0.0), g_);
  drilling_tool_ = drilling_tool;
  lever_model_ = lever_model;
  mech_.set_lever_model(lever_model_);
  mech_.set_unresolved_vibration(drilling_tool);
  x_ = NavState();
  x_.q = Eigen::Quaterniond(c_bn).normalized();
  clear_estimates();
}

void FilterState::clear_estimates() {
  bg_.setZero();
  ba_.setZero();
  lever_.setZero();
  gyro_spin_.setZero();
  gyro_g_.setZero();
  mag_axial_ = 0;
  forget_corrected();
}

ImuReading FilterState::corrected(const InputReading& in, const InputReading* earlier, bool samples_are_means,
                                  double dt_nominal) const {
  ImuReading r = without_estimates(in, earlier);
  if (samples_are_means && dt_nominal > 0) r.f = mean_to_instant(r.f, r.w, dt_nominal);
  return r;
}

void FilterState::as_read(InputReading& made_up, const InputReading* earlier, bool samples_are_means,
                          double dt_nominal) const {
  const ImuReading bare = without_estimates(made_up, earlier);
  const Eigen::Vector3d lever = (made_up.f - ba_) - bare.f;
  Eigen::Vector3d f = made_up.f - ba_;
  if (samples_are_means && dt_nominal > 0) f = instant_to_mean(f, bare.w, dt_nominal);
  made_up.f = f + lever + ba_;
}

ImuReading FilterState::without_estimates(const InputReading& in, const InputReading* earlier) const {
  ImuReading r{in.t, in.f - ba_, in.w - bg_};
  r.w.z() /= 1.0 + gyro_spin_.z();
  r.w.head<2>() -= gyro_spin_.head<2>() * r.w.z();
  r.w.noalias() -= gyro_g_matrix(in.f) * gyro_g_;
  if (lever_model_ && r.w.squaredNorm() > kTurningRate2) {
    r.f.noalias() -= centripetal_matrix(r.w) * lever_;
    if (earlier != nullptr && in.t > earlier->t) {
      const double spin_rate_change = (in.w.z() - earlier->w.z()) / ((in.t - earlier->t) * (1.0 + gyro_spin_.z()));
      r.f.head<2>() -= spin_rate_change * Eigen::Vector2d(-lever_.y(), lever_.x());
    }
  }
  return r;
}

bool FilterState::CorrectedReading::holds(const InputReading& in, const InputReading* earlier) const {
  if (!valid || r.t != in.t) return false;
  return earlier != nullptr ? earlier_t == earlier->t : std::isnan(earlier_t);
}

void FilterState::step(const InputReading& prev, const InputReading& in, const InputReading* prev2,
                       bool samples_are_means, double dt_nominal) {
  const auto keep = [](CorrectedReading& slot, const ImuReading& r, const InputReading* earlier) {
    slot.valid = true;
    slot.earlier_t = earlier != nullptr ? earlier->t : std::numeric_limits<double>::quiet_NaN();
    slot.r = r;
  };
  // The last step's later reading is this one's earlier, when corrected from the same reading
  // before it (the lever arm's tangential term takes the spin's change from it).
  ImuReading a = last_b_.holds(prev, prev2) ? last_b_.r : without_estimates(prev, prev2);
  ImuReading b = without_estimates(in, &prev);
  // Only the time and the rate of the reading before the step are read, and neither depends on the
  // reading before it: the last step's earlier reading serves whatever it was corrected from.
  ImuReading before;
  if (prev2 != nullptr) before = last_a_.valid && last_a_.r.t == prev2->t ? last_a_.r : without_estimates(*prev2, nullptr);
  keep(last_a_, a, prev2);
  keep(last_b_, b, &prev);
  if (samples_are_means && dt_nominal > 0) {
    a.f = mean_to_instant(a.f, a.w, dt_nominal);
    b.f = mean_to_instant(b.f, b.w, dt_nominal);
  }
  mech_.step(a, b, prev2 != nullptr ? &before : nullptr);
}

FilterState::Prediction FilterState::predict(const ProcessNoise& noise, const UnseenMotionNoise& unseen) {
  mech_.finish(x_, &integrals_);
  const bool left_out = drilling_tool_ && keep_gravity_and_axial_force(integrals_, g_);
  Prediction p{ErrorStateFilter::transition(integrals_, mech_.earth_rate()), integrals_.dt, noise};
  p.across_axis_force_left_out = left_out;
  kf_.predict(p.phi, p.dt, noise);
  if (integrals_.unresolved_dv2 > 0) {
    // What the readings could not resolve of a turning tool's vibration: across its axis, half in
    // each direction (the mechanization gathers it for a drilling tool).
    const Eigen::Vector3d axis = x_.q.toRotationMatrix().col(2);
    p.extra.velocity = (0.5 * integrals_.unresolved_dv2) * (Eigen::Matrix3d::Identity() - axis * axis.transpose());
  }
  p.extra.velocity += unseen.velocity;
  p.extra.displacement = unseen.displacement;
  p.extra.turn = unseen.turn;
  p.extra.attitude = unseen.attitude;
  add_noise(kf_.covariance(), p.extra);
  integrals_.clear();
  correction_.setZero();
  return p;
}

void FilterState::begin_steps() {
  integrals_.clear();
  mech_.begin(x_);
}

void FilterState::apply(const StateVector& dx) {
  feed_back(dx, x_, bg_, ba_, &lever_, &gyro_spin_, &mag_axial_, &gyro_g_);
  correction_ += dx;
  forget_corrected();
  g_ -= dx[kGravity];
  mech_.set_gravity(g_);
}

}  // namespace plumb::strapdown
