#include "plumb/strapdown/stop_updates.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>

#include "plumb/strapdown/measurements.hpp"

namespace plumb::strapdown {

using namespace index;

namespace {

// Seconds of motion the lateral velocity's measured excess remembers.
constexpr double kLateralMemoryS = 10;
// A drilling tool's lateral velocity, 1 sigma, is at most this (m/s): vibration of a few millimetres
// at tens of hertz. Innovations beyond it are the navigator's own velocity wandering (a turning tool
// read a few times per revolution: vibration the readings cannot resolve), process noise.
constexpr double kLateralVelocityCap = 0.05;

}  // namespace

double mean_force_sd(const StillStats& stats, double accel_vrw, double dt) {
  const double sd_f = std::max({stats.sample_sd_f(), accel_vrw / std::sqrt(dt), kMinSigmaAccel});
  return std::max(sd_f / std::sqrt(stats.count()), kMinMeanSdAccel);
}

void StopUpdates::reset(const NavigatorConfig& config) {
  config_ = config;
  zaru_stats_.clear();
  mag_stats_.clear();
  mag_done_this_period_ = false;
  depth0_ = 0;
  have_depth0_ = false;
  last_depth_update_t_ = -1e300;
  latest_depth_.reset();
  heave_.reset();
  aligned_ = false;
  heave_said_ = false;
  heave_found_since_.reset();
  notices_.clear();
  latest_depth_t_ = last_depth_row_t_ = 0;
  zupt_periods_ = 0;
  tally_stops_ = 0;
  stop_lag_s_ = 0;
  tally_distance_ = 0;
  stop_settled_ = false;
  last_field_warning_.clear();
  lateral_excess_.setZero();
  last_stop_attitude_.reset();
}

void StopUpdates::take_depth(double t, double depth, bool prev_had_depth, const FilterState& filter, bool still,
                             double depth_sd) {
  // A new report: a value that changed, or the first row with depth after rows without (a rig
  // reports once a second; the logger holds the value or leaves the rows between empty).
  if (!latest_depth_ || depth != *latest_depth_ || !prev_had_depth) {
    latest_depth_t_ = t;
    heave_.report(t, depth, still, depth_sd);
    // Said once the swell has been found for two minutes: its period is settled by then.
    if (!heave_.found()) heave_found_since_.reset();
    else if (!heave_found_since_) heave_found_since_ = t;
    if (heave_found_since_ && t - *heave_found_since_ >= kHeaveSettledS && !heave_said_) {
      heave_said_ = true;
      notices_.push_back(format("the depth reports carry a swell of about %.1f s (a floating rig's heave, found at "
                                "t = %.0f s): taken out of the depth at stops",
                                *heave_.period_s(), *heave_found_since_));
    }
  }
  latest_depth_ = depth;
  last_depth_row_t_ = t;
  if (!have_depth0_ && aligned_) {
    // The first depth after alignment: the distance counts from the one at alignment, so this
    // reading is referred back by the distance travelled since then.
    depth0_ = depth - filter.mechanization().state().s;
    have_depth0_ = true;
  }
}

void StopUpdates::follow(const InputReading& in, const StillnessState& still, Counters& counters) {
  if (still.started) {
    count(counters, "still_periods");
    ++zupt_periods_;
    mag_done_this_period_ = false;
    zaru_stats_.clear();
    mag_stats_.clear();
  }
  if (still.still) {
    zaru_stats_.add(in.f, in.w, std::nullopt, in.t);
    if (in.b) mag_stats_.add(in.f, in.w, in.b, in.t);
  }
}

void StopUpdates::at_alignment(FilterState& filter, const StillStats& stats, double sd_mean_f, double dt,
                               bool use_mag, const FieldReference& field, std::optional<double> depth,
                               Counters& counters) {
  // The still period of the alignment is the tally's stop 0, not a connection.
  stop_started_t_ = std::numeric_limits<double>::infinity();
  lateral_excess_.setConstant(config_.nhc_sd * config_.nhc_sd);
  const Eigen::Vector3d f = stats.mean_f(), w = stats.mean_w();
  const double n = stats.count();
  const double sd_w = std::max({stats.sample_sd_w(), filter.noise().gyro_arw / std::sqrt(dt)});
  filter.update(tilt(filter.state(), filter.accel_bias(), filter.gravity(), f, sd_mean_f));
  count(counters, "tilt_updates");
  filter.update(zero_rate(filter.state(), filter.gyro_bias(), filter.gyro_g(), filter.mechanization().earth_rate(), w,
                          f, std::max(sd_w / std::sqrt(n), kMinMeanSdGyro)));
  count(counters, "zero_rate_updates");
  if (use_mag) {
    mag_stats_ = stats;
    mag_done_this_period_ = false;
    magnetic_update(filter, field, counters);
  }
  mag_done_this_period_ = true;
  velocity_after_updates_ = filter.state().v;
  zaru_stats_.clear();
  mag_stats_.clear();
  zupt_periods_ = 1;
  aligned_ = true;
  // The reports of the alignment's stop, averaged (a floating rig's swell in one report would stay
  // in every distance after it); the aligning reading's own where there were none before it.
  if (depth || heave_.depth()) {
    depth0_ = heave_.depth().value_or(depth.value_or(0.0));
    have_depth0_ = true;
  }
}

void StopUpdates::at_epoch(FilterState& filter, const FilterState::Prediction& prediction,
                           const StillnessState& still, double t, double dt_nominal, double depth_sd,
                           double depth_tolerance_m, bool use_mag, const FieldReference& field, Counters& counters) {
  if (still.still) {
    // A drilling string that slows over seconds looks still to the inertial sensors before it is
    // (depth, when there is some, sees the creep): in the first seconds of such a stop the tool may
    // creep at the rate of penetration, and a stop that ends within them was none (no stop updates
    // at its end).
    const bool settling = filter.drilling_tool() && !latest_depth_ &&
                          t - still.period_start < config_.min_still_s + config_.stop_settle_s;
    stop_settled_ = !settling;
    filter.update(
        zero_velocity(filter.state(), settling ? std::max(config_.zupt_sd, config_.rop_sd) : config_.zupt_sd));
    count(counters, "zero_velocity_updates");
    if (!settling) still_updates(filter, false, dt_nominal, use_mag, field, counters);
  } else {
    if (still.ended) {
      if (stop_settled_) still_updates(filter, true, dt_nominal, use_mag, field, counters);
      late_stop_end(filter, depth_tolerance_m);
      last_stop_attitude_ = filter.state().q;
      stop_settled_ = false;
    }
    if (config_.lateral_velocity_update) lateral_velocity_update(filter, counters);
    axial_acceleration_update(filter, prediction, t, counters);
  }
  if (still.started) {
    stop_started_t_ = t;
    turned_since_last_stop(filter);
  }
  // (The filter runs stop_lag_s behind the stillness detector: a reading still at t is one the
  // detector saw still until t + stop_lag_s at least.)
  if (still.still && t + stop_lag_s_ - stop_started_t_ >= config_.pipe_connection_s) {
    tally_update(filter, counters);
    stop_started_t_ = std::numeric_limits<double>::infinity();  // once per stop
  }
  depth_update(filter, t, dt_nominal, depth_sd, still.still, counters);
  velocity_after_updates_ = filter.state().v;
}

bool StopUpdates::depth_reporting(double t) const { return latest_depth_ && t - last_depth_row_t_ <= kHeldDepthAgeS; }

void StopUpdates::depth_update(FilterState& filter, double t, double dt_nominal, double depth_sd, bool still,
                               Counters& counters) {
  // A report older than a held one (a feed that reports only at connections, or one that stopped)
  // says where the tool was, not where it is: it waits for the next.
  if (!depth_reporting(t) || !have_depth0_ || t - last_depth_update_t_ < config_.depth_interval_s - 0.5 * dt_nominal)
    return;
  // A report's age: the time since the last row that carried depth (depth only at connections,
  // or left empty between reports), plus how long a held value had stood then (a 1 Hz report held
  // on every row; at most kHeldDepthAgeS). A moving tool has gone on by its speed times that age,
  // which the update's sigma says.
  const NavState& x = filter.state();
  const double held = std::min(last_depth_row_t_ - latest_depth_t_, kHeldDepthAgeS);
  const double speed = x.q.toRotationMatrix().col(2).dot(x.v);
  const double stale_m = speed * (t - last_depth_row_t_ + held);
  // (A floating rig's swell taken out where one is found: heave_filter.hpp.)
  const double swell = still ? heave_.swell_at(latest_depth_t_) : 0.0;
  const double var = still ? heave_.residual_var(depth_sd) : depth_sd * depth_sd;
  filter.update(along_hole_distance(x, *latest_depth_ - swell - depth0_, std::sqrt(var + stale_m * stale_m)));
  count(counters, "depth_updates");
  last_depth_update_t_ = t;
}

ProcessNoise StopUpdates::process_noise(const ProcessNoise& base, const StillnessState& still,
                                        bool drilling_tool) const {
  ProcessNoise noise = base;
  if (!still.still && drilling_tool) {
    // The lateral innovations' excess beyond what a tool's lateral velocity can be: the velocity's
    // process noise carries it (isotropic, as the accelerometers' white noise).
    const double beyond = (lateral_excess_.array() - kLateralVelocityCap * kLateralVelocityCap).max(0.0).mean();
    noise.accel_vrw = std::sqrt(noise.accel_vrw * noise.accel_vrw + beyond * config_.kf_rate_hz);
  }
  return noise;
}

void StopUpdates::lateral_velocity_update(FilterState& filter, Counters& counters) {
  Measurement<2> m = lateral_velocity(filter.state(), config_.nhc_sd, filter.drilling_tool());
  // Covariance matching over the last kLateralMemoryS of motion: the innovations' mean square
  // beyond what the covariance explains is the tool's real lateral velocity (up to
  // kLateralVelocityCap; the rest is the velocity's process noise, process_noise()).
  // (A drilling tool's: a foot or a hand keeps the stated sigma.)
  if (filter.drilling_tool()) {
    const Eigen::Matrix<double, kStates, 2> pht = filter.p_ht(m);
    const Eigen::Vector2d excess = m.r.array().square() - (m.h.lazyProduct(pht)).diagonal().array();
    lateral_excess_ += std::min(1.0, 1.0 / (kLateralMemoryS * config_.kf_rate_hz)) * (excess - lateral_excess_);
    m.noise.diagonal() =
        lateral_excess_.cwiseMax(config_.nhc_sd * config_.nhc_sd).cwiseMin(kLateralVelocityCap * kLateralVelocityCap);
    filter.update(m, pht);
  } else {
    filter.update(m);
  }
  count(counters, "lateral_velocity_updates");
}

// Without depth nothing measures the speed along the axis between stops, and near horizontal a
// tilt error of 0.1 deg is 0.017 m/s^2 of it: the speed and the tilt would drift together, the
// speed to metres per second within minutes. The string's own acceleration along its axis is small
// (its rate of penetration changes over seconds), so the mechanization's along-axis acceleration
// over each epoch is a measurement of the tilt and the axial accelerometer bias. The string's
// acceleration is taken as correlated over a second (its variance per epoch grows as 1 s / dt),
// the accelerometers' white noise over the epoch adds to it.
// While depth reports come (a rig feed held or written once a second) they measure the speed along
// the axis themselves; a feed that reports only at connections, or one that has stopped, leaves the
// drilling between them to this update.
void StopUpdates::axial_acceleration_update(FilterState& filter, const FilterState::Prediction& prediction, double t,
                                            Counters& counters) {
  if (!(config_.axial_accel_sd > 0) || !filter.drilling_tool() || depth_reporting(t) || !(prediction.dt > 0)) return;
  const double dt = prediction.dt, vrw = filter.noise().accel_vrw;
  const double sd = std::sqrt(config_.axial_accel_sd * config_.axial_accel_sd / dt + vrw * vrw / dt);
  const Eigen::Vector3d axis = filter.state().q.toRotationMatrix().col(2);
  const Eigen::Vector3d dv = filter.state().v - velocity_after_updates_;
  const Eigen::Vector3d dv_turned =
      prediction.across_axis_force_left_out ? Eigen::Vector3d(axis * axis.dot(dv)) : dv;
  filter.update(axial_acceleration(axis, dv, dv_turned, prediction.phi, dt, sd));
  count(counters, "axial_acceleration_updates");
}

// A still period's end is seen late when the string speeds up slowly (its acceleration under the
// accelerometer noise): the zero-velocity updates held the velocity at zero while the tool already
// moved along its axis, at up to the rate of penetration. Said to the filter as velocity
// uncertainty along the axis at the end; depth, where there is some, takes it back out. The string
// may also have gone some way before the end was seen, along its axis and along the hole alike:
// with depth, up to what the depth test lets pass as still; without, the rate of penetration over
// stop_settle_s. One displacement: the position and the path length move together, and a later
// depth update corrects both.
void StopUpdates::late_stop_end(FilterState& filter, double depth_tolerance_m) const {
  if (!(config_.rop_sd > 0) || !filter.drilling_tool()) return;
  const Eigen::Vector3d axis = filter.state().q.toRotationMatrix().col(2);
  StateMatrix& p = filter.covariance();
  p.block<3, 3>(kVel, kVel) += (config_.rop_sd * config_.rop_sd) * axis * axis.transpose();
  const double missed = latest_depth_ ? depth_tolerance_m / std::sqrt(3.0) : config_.rop_sd * config_.stop_settle_s;
  Eigen::Vector4d j;
  j << axis, 1.0;
  const Eigen::Matrix4d add = (missed * missed) * j * j.transpose();
  p.block<3, 3>(kPos, kPos) += add.topLeftCorner<3, 3>();
  p.block<3, 1>(kPos, kDistance) += add.block<3, 1>(0, 3);
  p.block<1, 3>(kDistance, kPos) += add.block<1, 3>(3, 0);
  p(kDistance, kDistance) += add(3, 3);
}

// The accelerometers' scale factors and misalignments read gravity as a bias that depends on how it
// falls on the triad: (K - I) C_n^b g, which goes round twice per turn of the toolface. A stop after
// the tool turned by an angle a sees that part changed by about 2 a g sigma_K, and by the difference
// of two independent draws (variance 2 (g sigma_K)^2) after a quarter turn or more: the bias the last
// stop found is that much less known (and the gyros', gyro_g_bias_after_turn).
void StopUpdates::turned_since_last_stop(FilterState& filter) const {
  if (!last_stop_attitude_ || !filter.drilling_tool()) return;
  const Eigen::AngleAxisd turn(filter.state().q * last_stop_attitude_->conjugate());
  gyro_g_bias_after_turn(filter, turn.angle());
  const double sd_k = std::hypot(config_.accel_scale_sd, config_.accel_misalignment_sd);
  if (!(sd_k > 0)) return;
  const double share = std::min(2.0, 4.0 * turn.angle() * turn.angle());
  const double g = filter.gravity();
  filter.covariance().block<3, 3>(kAccelBias, kAccelBias).diagonal().array() += share * (g * sd_k) * (g * sd_k);
}

// The gyros' sensitivity to the specific force reads gravity's part across the axis, g sin I, as a
// bias that goes round once per turn of the toolface. The filter estimates what a turning tool
// rectifies of the x and y gyros' (kGyroG); the rest, the symmetric traceless part of their 2 x 2
// block (two terms of variance sigma^2 / 2) and the z gyro's response to the lateral force (two of
// sigma^2), changes at a stop after a turn by a: by a variance 2 (1 - cos a) times theirs. A noisier
// MEMS gyro (18 deg/h per g) at 37 deg: the z gyro's bias found by the stop before a rotary segment
// 25 deg/h off after it, its sigma 1.8 deg/h, and the azimuth drifted 0.5 deg through the stop.
void StopUpdates::gyro_g_bias_after_turn(FilterState& filter, double angle) const {
  const double sd = config_.gyro_g_sensitivity_sd;
  if (!(sd > 0)) return;
  const double cos_i = filter.state().q.toRotationMatrix()(2, 2);
  const double lateral = filter.gravity() * std::sqrt(std::max(0.0, 1.0 - cos_i * cos_i));
  const double v = 2.0 * (1.0 - std::cos(angle)) * (sd * lateral) * (sd * lateral);
  auto bias = filter.covariance().block<3, 3>(kGyroBias, kGyroBias).diagonal().array();
  bias += Eigen::Array3d(0.5 * v, 0.5 * v, v);
}

void StopUpdates::tally_update(FilterState& filter, Counters& counters) {
  if (config_.pipe_tally_m.empty() || latest_depth_) return;  // measured depth, when there is one, wins
  if (!config_.pipe_tally_repeats && tally_stops_ >= config_.pipe_tally_m.size()) return;
  const double joint = config_.pipe_tally_m[config_.pipe_tally_repeats ? 0 : tally_stops_];
  // A long still period inside a slide (a slow start unseen, then a steady speed) looks like a
  // connection: where the filter is sure (3 sigma) that the tool has not gone half a joint since
  // the last connection, it is none, and the tally waits for the next.
  const double moved = filter.state().s - tally_distance_;
  if (joint > 0 && moved < 0.5 * joint - 3.0 * std::sqrt(filter.covariance()(kDistance, kDistance))) {
    count(counters, "stops_not_connections");
    return;
  }
  ++tally_stops_;
  filter.update(along_hole_distance(filter.state(), tally_distance_ + joint,
                                    config_.pipe_tally_sd * std::sqrt(static_cast<double>(tally_stops_))));
  count(counters, "tally_updates");
  tally_distance_ += joint;
}

void StopUpdates::still_updates(FilterState& filter, bool period_end, double dt_nominal, bool use_mag,
                                const FieldReference& field, Counters& counters) {
  const double dt = dt_nominal > 0 ? dt_nominal : 0.01;
  const double n = zaru_stats_.count();
  if (n >= StillnessConfig::kMinWindowSamples && (period_end || zaru_stats_.duration() >= config_.zaru_interval_s)) {
    const double sd_w = std::max(zaru_stats_.sample_sd_w(), filter.noise().gyro_arw / std::sqrt(dt));
    filter.update(zero_rate(filter.state(), filter.gyro_bias(), filter.gyro_g(), filter.mechanization().earth_rate(),
                            zaru_stats_.mean_w(), zaru_stats_.mean_f(), std::max(sd_w / std::sqrt(n), kMinMeanSdGyro)));
    count(counters, "zero_rate_updates");
    if (config_.tilt_update) {
      filter.update(tilt(filter.state(), filter.accel_bias(), filter.gravity(), zaru_stats_.mean_f(),
                         mean_force_sd(zaru_stats_, filter.noise().accel_vrw, dt)));
      count(counters, "tilt_updates");
    }
    zaru_stats_.clear();
  }
  if (use_mag && !mag_done_this_period_ && mag_stats_.mag_count() >= StillnessConfig::kMinWindowSamples &&
      (period_end || mag_stats_.duration() >= config_.mag_update_s)) {
    magnetic_update(filter, field, counters);
  }
  if (period_end) {
    zaru_stats_.clear();
    mag_stats_.clear();
  }
}

// The dip is read with the accelerometers' bias and the part of gravity their scale factors and
// misalignments take for one, (K - I) C g: both lean the measured gravity by up to their size over
// g, differently at every toolface, and the reference was read at the first stop's. Between two
// toolfaces the dip then differs by up to sqrt(2) times that: for a noisier MEMS package (3 mg,
// 1000 ppm, 1 mrad) 0.27 deg, 1 sigma, which skipped the azimuth update of an undisturbed stop after
// a rotary segment on outside runs and left the azimuth to the gyros (1.1 deg off at the next
// stop). The gate allows three times that beside dip_tol_deg.
double StopUpdates::dip_tolerance(double g) const {
  const double lean =
      std::hypot(config_.accel_bias_sd, g * std::hypot(config_.accel_scale_sd, config_.accel_misalignment_sd)) / g;
  return std::hypot(config_.dip_tol, 3.0 * std::numbers::sqrt2 * lean);
}

void StopUpdates::magnetic_update(FilterState& filter, const FieldReference& field, Counters& counters) {
  mag_done_this_period_ = true;
  // The gate sees the field as read, as the references learnt at alignment did; the heading, the
  // field less the axial bias the filter estimates.
  const Eigen::Vector3d raw_b = mag_stats_.mean_b(), f = mag_stats_.mean_f();
  const Eigen::Vector3d b = raw_b - filter.mag_axial_bias() * Eigen::Vector3d::UnitZ();
  const double total = raw_b.norm(), dip = dip_of(f, raw_b);
  const double deg = std::numbers::pi / 180.0;
  if (std::abs(total - field.total_uT.value_or(total)) > config_.field_tol_uT ||
      std::abs(dip - field.dip.value_or(dip)) > dip_tolerance(filter.gravity())) {
    count(counters, "disturbed_field");
    last_field_warning_ = format("azimuth update skipped at a stop: field disturbed (|B| %.2f uT, dip %.2f deg; reference %.2f uT, ",
                                 total, dip / deg, field.total_uT.value_or(total)) +
                          format("%.2f deg)", field.dip.value_or(dip) / deg);
    return;
  }
  const double bh = total * std::cos(dip);
  if (!(bh > 0)) return;
  const double n = mag_stats_.mag_count();
  const double sd_b = mag_stats_.sample_sd_b();
  const double sd = std::sqrt(sd_b * sd_b / n / (bh * bh) + config_.mag_heading_sd * config_.mag_heading_sd);
  // The field's azimuth in the navigation frame: the declination in a true frame, 0 in a magnetic one.
  filter.update(magnetic_heading(filter.state(), b, config_.declination.value_or(0.0), sd));
  count(counters, "azimuth_updates");
  last_field_warning_.clear();
}

}  // namespace plumb::strapdown
