#include "plumb/strapdown/stillness_watch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "plumb/strapdown/earth.hpp"
#include "plumb/strapdown/rotation.hpp"

namespace plumb::strapdown {

using namespace index;

namespace {

// The range of a second of depth readings: white noise per reading spans about 6 sigma over a few
// hundred readings (and a held 1 Hz report up to 5 sigma between two reports).
constexpr double kDepthRangeSigmas = 8.0;
// 3 sigma of a bias on each of three axes: the largest bias vector the sensor's figures allow.
constexpr double kBiasSigmas = 3.0 * std::numbers::sqrt3;

}  // namespace

void StillnessWatch::reset(const NavigatorConfig& config) {
  config_ = config;
  aligned_ = false;
  aligned_gyro_tol_ = 0;
  detector_ba_.setZero();
  detector_bg_.setZero();
  tool_attitude_ = Eigen::Quaterniond::Identity();
  turns_.clear();
  earth_rate_tool0_.setZero();
  StillnessConfig sc;
  sc.mode = config_.detector == DetectorChoice::Glrt ? StillnessConfig::Mode::Glrt : StillnessConfig::Mode::Magnitude;
  if (config_.detector == DetectorChoice::Auto && !config_.use_magnetometer) sc.mode = StillnessConfig::Mode::Glrt;
  sc.window_s = config_.still_window_s;
  sc.min_still_s = config_.min_still_s;
  sc.hysteresis = config_.still_hysteresis;
  sc.accel_tol = config_.still_accel_tol;
  sc.field_tol_uT = config_.still_field_tol_uT;
  sc.gyro_tol = config_.still_gyro_tol;
  sc.glrt_threshold = config_.glrt_threshold;
  sc.accel_drift_tol = config_.still_accel_drift_tol;
  sc.depth_tol_m = config_.still_depth_tol_m;
  detector_.configure(sc);
  noise_floor_.clear();
  floor_blocks_used_ = 0;
  measured_sigma_a_.reset();
  measured_sigma_w_.reset();
  measured_depth_sd_.reset();
  depth_sd_ = config_.depth_sd;
  refresh_depth_tolerance();
  first_t_.reset();
  depth_seen_ = false;
  tally_.clear();
  align_notice_given_ = stop_notice_given_ = depth_raised_notice_given_ = false;
  last_still_t_ = 0;
  notices_.clear();
}

void StillnessWatch::use_glrt_without_field() {
  if (config_.detector != DetectorChoice::Auto || detector_.config().mode != StillnessConfig::Mode::Magnitude) return;
  StillnessConfig sc = detector_.config();
  sc.mode = StillnessConfig::Mode::Glrt;
  detector_.configure(sc);
}

void StillnessWatch::field_deviation(const InputReading& in, std::optional<double> b0, StillnessInput& si) const {
  if (in.b && detector_.config().mode == StillnessConfig::Mode::Magnitude && config_.use_magnetometer && b0) {
    si.field_deviation_uT = in.b_norm - *b0;
  }
}

StillnessInput StillnessWatch::raw_input(const InputReading& in, std::optional<double> b0) const {
  StillnessInput si;
  si.t = in.t;
  si.depth_m = in.depth;
  si.f = in.f;
  si.w_minus_expected = in.w;
  si.extra_gyro_tol = kEarthRate + 3.0 * config_.gyro_bias_sd;
  si.g = config_.gravity.value_or(in.f.norm());
  // A given gravity against readings whose bias is not known yet: 3 sigma of the stated bias
  // along the specific force (the filter takes it out once aligned).
  if (config_.gravity) si.extra_accel_tol = 3.0 * config_.accel_bias_sd;
  field_deviation(in, b0, si);
  return si;
}

StillnessInput StillnessWatch::aligned_input(const InputReading& in, const FilterState& filter,
                                             std::optional<double> b0) const {
  StillnessInput si;
  si.t = in.t;
  si.depth_m = in.depth;
  // The biases as the filter has them, but never beyond 3 sigma of what the sensor's figures
  // allow: a filter that has drifted off (no depth, a missed stop) must not blind the detector
  // to the very stops that would bring it back. (refresh_allowances keeps them, once per epoch.)
  si.f = in.f - detector_ba_;
  si.w_minus_expected = in.w - detector_bg_ -
                        (lagging_ ? Eigen::Vector3d(tool_attitude_.conjugate() * earth_rate_tool0_)
                                  : filter.mechanization().earth_rate_in_tool());
  si.extra_gyro_tol = aligned_gyro_tol_;
  si.g = filter.gravity();
  field_deviation(in, b0, si);
  return si;
}

StillnessState StillnessWatch::before_alignment(const InputReading& in, std::optional<double> b0) {
  watch_before_alignment(in);
  const StillnessInput si = raw_input(in, b0);
  StillnessState state;
  if (in.gyro_bad || in.accel_bad) {
    const bool was_still = detector_.still();
    detector_.reset();
    state.ended = was_still;
  } else {
    state = detector_.update(si);
    // Noise neither stated nor measured yet: a still period cannot be judged, so none starts.
    if (!noise_known()) state = StillnessState();
  }
  if (!state.still) tally_.add(detector_.binding_check(si.extra_gyro_tol));
  return state;
}

StillnessState StillnessWatch::aligned(const InputReading& in, const FilterState& filter, std::optional<double> b0) {
  if (lagging_) turn_with(in);
  if (in.depth && !config_.depth_noise_stated) {
    noise_floor_.add_depth(in.t, in.depth);
    if (noise_floor_.blocks() != floor_blocks_used_) {
      floor_blocks_used_ = noise_floor_.blocks();
      adopt_depth_floor();
    }
  }
  const bool was_still = detector_.still();
  if (in.gyro_bad || in.accel_bad) {
    detector_.reset();
    StillnessState state;
    state.ended = was_still;
    return state;
  }
  return detector_.update(aligned_input(in, filter, b0));
}

// The filter runs behind the detector (stillness_lag.hpp): the detector takes the earth rate out
// with the tool's attitude carried forward from the filter's by the readings since. (While the tool
// turns, the filter's own toolface of seconds ago would misplace the earth rate by up to twice its
// horizontal part; the biases and allowances below change slowly, and the filter's lagging ones do.)
void StillnessWatch::turn_with(const InputReading& in) {
  if (!turns_.empty() && in.t > turns_.back().first) {
    tool_attitude_ *= quaternion_from_rotation_vector((in.w - detector_bg_) * (in.t - turns_.back().first));
    tool_attitude_.normalize();
  }
  turns_.emplace_back(in.t, tool_attitude_);
}

void StillnessWatch::follow_filter(const FilterState& filter, double t) {
  if (!lagging_) return;
  while (turns_.size() > 1 && turns_[1].first <= t) turns_.pop_front();
  if (turns_.empty()) return;
  earth_rate_tool0_ = turns_.front().second * (filter.state().q.conjugate() * filter.mechanization().earth_rate());
}

void StillnessWatch::refresh_allowances(const FilterState& filter, double t) {
  follow_filter(filter, t);
  const StateMatrix& p = filter.covariance();
  const double bias_sd = std::sqrt(p.block<3, 3>(kGyroBias, kGyroBias).diagonal().maxCoeff());
  const double att_sd = std::sqrt(p.block<3, 3>(kAtt, kAtt).diagonal().maxCoeff());
  aligned_gyro_tol_ = 3.0 * bias_sd + 3.0 * std::min(att_sd, 1.0) * kEarthRate;
  // (The GLRT detector of a foot or a hand keeps the filter's own: its users state the noise and
  // leave the biases to the filter.)
  const bool bound = detector_.config().mode == StillnessConfig::Mode::Magnitude;
  const auto bounded = [bound](const Eigen::Vector3d& b, double limit) -> Eigen::Vector3d {
    const double n = b.norm();
    return bound && n > limit ? Eigen::Vector3d(b * (limit / n)) : b;
  };
  detector_ba_ = bounded(filter.accel_bias(), kBiasSigmas * config_.accel_bias_sd);
  detector_bg_ = bounded(filter.gyro_bias(), kBiasSigmas * config_.gyro_bias_sd);
}

void StillnessWatch::refresh_noise(double dt) {
  if (!(dt > 0)) return;
  const double sigma_a = measured_sigma_a_.value_or(config_.accel_vrw / std::sqrt(dt));
  const double sigma_w = measured_sigma_w_.value_or(config_.gyro_arw / std::sqrt(dt));
  detector_.set_noise(std::max(sigma_a, kMinSigmaAccel), std::max(sigma_w, kMinSigmaGyro));
}

// Stated depth noise sets the depth test's limit from the start; unstated, the test waits for the
// noise the reports show, so that a noisy rig feed cannot hold off every still period meanwhile.
void StillnessWatch::refresh_depth_tolerance() {
  double tol = std::numeric_limits<double>::infinity();
  if (config_.depth_noise_stated) {
    tol = std::max(config_.still_depth_tol_m, kDepthRangeSigmas * config_.depth_sd);
  } else if (measured_depth_sd_ || aligned_) {
    // Aligned without a measured noise: the reports never changed while still (exact depth).
    tol = std::max(config_.still_depth_tol_m, kDepthRangeSigmas * measured_depth_sd_.value_or(0.0));
  }
  detector_.set_depth_tolerance(tol);
  detector_.set_depth_noise(config_.depth_noise_stated ? config_.depth_sd : measured_depth_sd_.value_or(0.0));
}

// Before alignment: what the user did not state of the noise is read off the data, and a run that
// has not aligned after notice_after_s of data says why, once.
void StillnessWatch::watch_before_alignment(const InputReading& in) {
  if (!first_t_) first_t_ = in.t;
  // still_detector=auto: a tool without a field is a foot or a hand (the GLRT) unless it has a
  // measured depth, which only a drill string has: a gyro-only drilling tool is one again.
  if (in.depth && !depth_seen_ && config_.detector == DetectorChoice::Auto && mode() == StillnessConfig::Mode::Glrt) {
    StillnessConfig sc = detector_.config();
    sc.mode = StillnessConfig::Mode::Magnitude;
    detector_.configure(sc);
  }
  depth_seen_ = depth_seen_ || in.depth.has_value();
  noise_floor_.add(in.t, in.f, in.w, in.depth);
  if (noise_floor_.blocks() != floor_blocks_used_) adopt_noise_floor();
  if (align_notice_given_ || in.t - *first_t_ < config_.notice_after_s) return;
  align_notice_given_ = true;
  notices_.push_back(format("not aligned after %.0f s of data: no still period of %.1f s found. ", in.t - *first_t_,
                            config_.min_still_s) +
                     failing_test_text());
}

bool StillnessWatch::noise_known() const {
  if (detector_.config().mode != StillnessConfig::Mode::Magnitude) return true;
  return (config_.accel_noise_stated || measured_sigma_a_) && (config_.gyro_noise_stated || measured_sigma_w_);
}

void StillnessWatch::adopt_noise_floor() {
  floor_blocks_used_ = noise_floor_.blocks();
  if (detector_.config().mode == StillnessConfig::Mode::Magnitude) {
    if (!config_.accel_noise_stated) measured_sigma_a_ = noise_floor_.accel_sd();
    if (!config_.gyro_noise_stated) measured_sigma_w_ = noise_floor_.gyro_sd();
  }
  adopt_depth_floor();
}

// Once aligned, the depth's noise changes only when the reports show more than the filter takes
// (a swell that starts or grows): a floor that falls (the sea calms, or the quiet blocks of an
// exact simulated depth) would make the depth updates trust a swell between its crests, or arm the
// detector's test on means with no noise at all.
void StillnessWatch::adopt_depth_floor() {
  const auto floor = noise_floor_.depth_sd();
  if (config_.depth_noise_stated || !floor) return;
  if (aligned_ && *floor <= depth_sd_) return;
  const double before = depth_sd_;
  measured_depth_sd_ = floor;
  depth_sd_ = std::max(config_.depth_sd, *floor);
  refresh_depth_tolerance();
  if (aligned_ && !depth_raised_notice_given_ && depth_sd_ > 2 * before) {
    depth_raised_notice_given_ = true;
    notices_.push_back(format("the depth reports wander by %.3g m rms about their trend over %.0f s (a floating rig's heave?): "
                              "their noise raised from %.3g m; state depth_sd_m if the rig's figure is known",
                              depth_sd_, DepthNoiseFloor::kLineBlockSeconds, before));
  }
}

// (A preset is a class of sensors, not this one.)
void StillnessWatch::adopt_measured_noise(double dt, ProcessNoise& noise) {
  const double root_dt = std::sqrt(dt);
  if (measured_sigma_w_) noise.gyro_arw = std::max(config_.gyro_arw, *measured_sigma_w_ * root_dt);
  if (measured_sigma_a_) noise.accel_vrw = std::max(config_.accel_vrw, *measured_sigma_a_ * root_dt);
  if (!measured_sigma_a_ && !measured_sigma_w_ && !measured_depth_sd_) return;
  const auto said = [](bool measured) { return measured ? "measured" : "stated"; };
  const StillnessConfig& d = detector_.config();
  std::string text = format("noise per sample behind the stillness limits and the filter: accelerometer %.3g m/s^2 (", d.sigma_a) +
         said(measured_sigma_a_.has_value()) + format("), gyro %.3g deg/h (", d.sigma_w * kRadPerSecToDegPerHour) +
         said(measured_sigma_w_.has_value()) + ")";
  if (measured_depth_sd_) text += format(", depth %.3g m (measured)", *measured_depth_sd_);
  notices_.push_back(text);
}

void StillnessWatch::on_aligned(double t, bool lagging) {
  aligned_ = true;
  lagging_ = lagging;
  tool_attitude_ = Eigen::Quaterniond::Identity();
  turns_.clear();
  turns_.emplace_back(t, tool_attitude_);
  refresh_depth_tolerance();
  tally_.clear();
  last_still_t_ = t;
  // From now on the detector sees w less the expected earth rate and bias: its long means restart.
  detector_.restart_stretch();
  // still_detector=auto took a tool with neither a field nor a measured depth for a foot or a hand:
  // a gyro-only drilling tool without a depth feed looks the same, and only its user knows.
  if (config_.detector == DetectorChoice::Auto && mode() == StillnessConfig::Mode::Glrt)
    notices_.push_back(
        "no magnetometer and no measured depth before the alignment: navigated as a foot or a hand "
        "(still_detector=auto chose the GLRT detector, without a drill string's model); a drilling tool "
        "without either: give still_detector=magnitude");
}

// (The zero-velocity updates are what bounds the drift.)
void StillnessWatch::watch_for_stops(double t, bool still) {
  if (still) {
    last_still_t_ = t;
    tally_.clear();
    stop_notice_given_ = false;
    return;
  }
  tally_.add(detector_.binding_check(aligned_gyro_tol_));
  if (stop_notice_given_ || t - last_still_t_ < config_.no_stop_notice_s) return;
  stop_notice_given_ = true;
  notices_.push_back(format("no still period for %.0f s (since t = %.1f s): no zero-velocity update bounds the drift. ",
                            t - last_still_t_, last_still_t_) +
                     failing_test_text());
}

std::string StillnessWatch::not_aligned_reason() const {
  if (!align_notice_given_) return {};
  // The row's reason is short (the attitude topic bounds it); the notice says the rest.
  return "not aligned: no still period (" + std::string(test_name(tally_.most_frequent().test)) + " too large)";
}

// The detector's test that failed most often, at its closest approach to its limit, and the
// parameter that sets that limit.
std::string StillnessWatch::failing_test_text() const {
  using Test = StillnessCheck::Test;
  const StillnessCheck c = tally_.most_frequent();
  const auto noise = [&](const std::string& sensor, double sigma, const std::string& unit, bool stated,
                         const std::string& parameter) {
    return " (set by the " + sensor + " noise, " + format("%.3g", sigma) + " " + unit +
           (stated ? ", as stated in " : ", read off the data; state it with ") + parameter + ")";
  };
  std::string text = "The test that failed most: " + std::string(test_name(c.test)) + ", at best ";
  const double sigma_a = detector_.config().sigma_a, sigma_w = detector_.config().sigma_w;
  switch (c.test) {
    case Test::Acceleration:
      return text + format("%.3g m/s^2 against its limit %.3g", c.statistic, c.limit) +
             noise("accelerometer", sigma_a, "m/s^2 per sample", config_.accel_noise_stated, "accel_vrw_mps_rt_h") +
             "; or raise still_accel_tol";
    case Test::ForceSteadiness:
      return text + format("%.3g m/s^2 against its limit %.3g", c.statistic, c.limit) +
             noise("accelerometer", sigma_a, "m/s^2 per sample", config_.accel_noise_stated, "accel_vrw_mps_rt_h") +
             "; or raise still_accel_drift_tol";
    case Test::GyroWindow:
    case Test::GyroStretch:
      return text + format("%.3g deg/h against its limit %.3g", c.statistic * kRadPerSecToDegPerHour,
                           c.limit * kRadPerSecToDegPerHour) +
             noise("gyro", sigma_w * kRadPerSecToDegPerHour, "deg/h per sample", config_.gyro_noise_stated,
                   "gyro_arw_deg_rt_h") +
             "; state the gyro bias with gyro_bias_dph, or raise still_gyro_tol_dph";
    case Test::Field:
      return text + format("%.3g uT against its limit %.3g: the field is disturbed or still_field_tol_uT is too small",
                           c.statistic, c.limit);
    case Test::Glrt:
      return text + format("%.3g against glrt_threshold %.3g: state the sensor noise (gyro_arw_deg_rt_h, accel_vrw_mps_rt_h) or raise glrt_threshold",
                           c.statistic, c.limit);
    case Test::Depth:
      return text + format("%.3g m against its limit %.3g: state the depth noise with depth_sd_m or raise still_depth_tol_m",
                           c.statistic, c.limit);
    case Test::None:
      break;
  }
  return "No sample failed a stillness test: the quiet stretches were shorter than min_still_s, or no reading could be "
         "tested (gaps, saturated sensors).";
}

}  // namespace plumb::strapdown
