#include "plumb/strapdown/navigator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "plumb/core/attitude.hpp"
#include "plumb/strapdown/attitude_output.hpp"
#include "plumb/strapdown/earth.hpp"
#include "plumb/strapdown/measurements.hpp"
#include "plumb/strapdown/rotation.hpp"

namespace plumb::strapdown {

using namespace index;

namespace {
// Seconds of motion the lateral velocity's measured excess remembers.
constexpr double kLateralMemoryS = 10;
// A drilling tool's lateral velocity, 1 sigma, is at most this (m/s): vibration of a few millimetres
// at tens of hertz. Innovations beyond it are the navigator's own velocity wandering (a turning tool
// read a few times per revolution: vibration the readings cannot resolve), process noise.
constexpr double kLateralVelocityCap = 0.05;


constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// Magnetometer readings below this are "no magnetometer" (a logger without one writes zeros).
constexpr double kNoFieldUT = 1e-3;
// Noise floors: a perfect simulated sensor must not make the detector or the filter divide by 0.
constexpr double kMinSigmaAccel = 1e-3;    // m/s^2 per sample
constexpr double kMinSigmaGyro = 1e-6;     // rad/s per sample
constexpr double kMinMeanSdGyro = 1e-9;    // rad/s, a zero-rate update's mean
constexpr double kMinMeanSdAccel = 1e-6;   // m/s^2, a tilt update's mean
// The range of a second of depth readings: white noise per reading spans about 6 sigma over a few
// hundred readings (and a held 1 Hz report up to 5 sigma between two reports).
constexpr double kDepthRangeSigmas = 8.0;
constexpr double kRadPerSecToDegPerHour = kRadToDeg * 3600.0;
// 3 sigma of a bias on each of three axes: the largest bias vector the sensor's figures allow.
constexpr double kBiasSigmas = 3.0 * std::numbers::sqrt3;
// A rig reports depth about once a second: a held value is at most this old while the tool moves.
constexpr double kHeldDepthAge = 2.0;

// The σ of a still stretch's mean specific force (a tilt measurement): the scatter seen, never
// below the sensor's white noise or the floor.
double mean_force_sd(const StillStats& stats, double accel_vrw, double dt) {
  const double sd_f = std::max({stats.sample_sd_f(), accel_vrw / std::sqrt(dt), kMinSigmaAccel});
  return std::max(sd_f / std::sqrt(stats.count()), kMinMeanSdAccel);
}

std::string format(const char* fmt, double a, double b = 0, double c = 0) {
  char text[200];
  std::snprintf(text, sizeof text, fmt, a, b, c);
  return text;
}

// sin(dip) = G.B / (|G||B|) with G = -f at rest (docs/conventions.md).
double dip_of(const Eigen::Vector3d& f, const Eigen::Vector3d& b) {
  const double den = f.norm() * b.norm();
  return den > 0 ? std::asin(std::clamp(-f.dot(b) / den, -1.0, 1.0)) : 0.0;
}

}  // namespace

Navigator::Navigator(const NavigatorConfig& config) { configure(config); }

void Navigator::configure(const NavigatorConfig& config) {
  config_ = config;
  reset();
}

void Navigator::reset() {
  counters_.clear();
  for (const char* name :
       {"samples", "accepted", "non_finite", "time_backwards", "repeated_time", "no_gyro", "gyro_saturated",
        "accel_saturated", "mag_unusable", "out_of_range", "gaps", "accel_in_g", "still_periods",
        "zero_velocity_updates", "zero_rate_updates", "tilt_updates", "azimuth_updates", "disturbed_field",
        "lateral_velocity_updates", "depth_updates", "tally_updates", "rows", "invalid_rows"}) {
    counters_[name] = 0;
  }
  // Map nodes stay where they are: the per-sample counters are bumped through pointers, not looked up.
  samples_counter_ = &counters_["samples"];
  accepted_counter_ = &counters_["accepted"];
  last_t_.reset();
  last_good_w_.reset();
  last_good_f_.reset();
  shift_queue_.clear();
  gyro_history_.clear();
  dt_nominal_ = 0;
  saw_gyro_ = saw_no_gyro_ = saw_mag_ = false;
  g_ = config_.gravity.value_or(9.80665);
  b0_ = config_.field_uT;
  dip0_ = config_.dip;
  accel_in_g_ = false;
  accel_in_g_level_ = 0;
  use_mag_ = false;
  azimuth_reference_ = config_.declination ? "true" : "magnetic";
  aligned_ = false;
  aligned_gyro_tol_ = 0;
  detector_ba_.setZero();
  detector_bg_.setZero();
  aligned_at_ = 0;
  x_ = NavState();
  bg_.setZero();
  ba_.setZero();
  lever_.setZero();
  gyro_spin_.setZero();
  mag_axial_ = 0;
  lever_model_ = false;
  kf_ = ErrorStateFilter();
  noise_.gyro_arw = config_.gyro_arw;
  noise_.accel_vrw = config_.accel_vrw;
  noise_.gyro_bias_walk = config_.gyro_bias_instability / std::sqrt(config_.bias_time_s);
  noise_.accel_bias_walk = config_.accel_bias_instability / std::sqrt(config_.bias_time_s);
  integrals_.clear();
  prev_.reset();
  prev2_.reset();
  last_epoch_t_ = 0;
  correction_.setZero();
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
  tally_.clear();
  align_notice_given_ = stop_notice_given_ = false;
  last_still_t_ = 0;
  notices_.clear();
  still_state_ = StillnessState();
  align_stats_.clear();
  zaru_stats_.clear();
  mag_stats_.clear();
  mag_done_this_period_ = false;
  depth0_ = 0;
  have_depth0_ = false;
  last_depth_update_t_ = -1e300;
  latest_depth_.reset();
  latest_depth_t_ = last_depth_row_t_ = 0;
  zupt_periods_ = 0;
  tally_stops_ = 0;
  tally_distance_ = 0;
  last_field_warning_.clear();
  gap_warning_until_ = -1;
  next_output_t_ = 0;
  output_started_ = false;
  last_row_t_ = 0;
  row_stats_.clear();
  last_b_valid_ = false;
  smoother_.clear();
  last_phi_.setIdentity();
  last_phi_dt_ = 0;
  pending_.clear();
}

// ---- input -------------------------------------------------------------------------------------

bool Navigator::accept(const Sample& s, Input& in) {
  ++*samples_counter_;
  const bool has_gyro = (s.flags & flags::kHasGyro) != 0;
  if ((s.flags & flags::kNotFinite) != 0 || !std::isfinite(s.t) || !s.f.allFinite() ||
      (has_gyro && !s.w.allFinite())) {
    count("non_finite");
    return false;
  }
  if ((s.flags & flags::kTimeBackwards) != 0 || (last_t_ && s.t < *last_t_)) {
    count("time_backwards");
    return false;
  }
  if (last_t_ && s.t == *last_t_) {
    count("repeated_time");
    return false;
  }
  if ((s.flags & flags::kOutOfRange) != 0) {
    count("out_of_range");
    return false;
  }
  in.t = s.t;
  if (!has_gyro) {
    // Rows keep coming (invalid, saying why); the sample itself cannot be navigated.
    count("no_gyro");
    saw_no_gyro_ = true;
    last_t_ = s.t;
    return false;
  }
  saw_gyro_ = true;
  in.w = s.w;
  if ((s.flags & flags::kGyroSaturated) != 0) {
    count("gyro_saturated");
    if (!last_good_w_) return false;
    in.w = *last_good_w_;
    in.gyro_bad = true;
  } else {
    last_good_w_ = s.w;
  }
  in.f = s.f;
  if ((s.flags & flags::kAccelSaturated) != 0) {
    count("accel_saturated");
    if (!last_good_f_) return false;
    in.f = *last_good_f_;
    in.accel_bad = true;
  } else {
    last_good_f_ = s.f;
  }
  if ((s.flags & flags::kMagSaturated) != 0 || !s.b.allFinite()) {
    count("mag_unusable");
  } else if (s.b.norm() > kNoFieldUT) {
    in.b = s.b;
    saw_mag_ = true;
  }
  // still_detector=auto: the magnitude test leans on |B|. A stream whose first sample has no
  // field (no bx,by,bz columns, or a tool without magnetometers) gets the GLRT, as
  // use_magnetometer=0 does.
  if (!last_t_ && !in.b && config_.detector == DetectorChoice::Auto &&
      detector_.config().mode == StillnessConfig::Mode::Magnitude) {
    StillnessConfig sc = detector_.config();
    sc.mode = StillnessConfig::Mode::Glrt;
    detector_.configure(sc);
  }
  if ((s.flags & flags::kHasDepth) != 0 && std::isfinite(s.depth_m)) in.depth = s.depth_m;
  if (last_t_) {
    const double dt = s.t - *last_t_;
    if (dt > config_.max_gap_s) {
      count("gaps");
      gap_warning_until_ = s.t + 1.0 / config_.output_rate_hz;
      detector_.reset();
    } else {
      dt_nominal_ = dt_nominal_ > 0 ? 0.99 * dt_nominal_ + 0.01 * dt : dt;
    }
  }
  last_t_ = s.t;
  ++*accepted_counter_;
  return true;
}

void Navigator::push(const Sample& s, std::vector<Estimate>& out) {
  Input in;
  if (!accept(s, in)) {
    if (!aligned_ && last_t_) emit(*last_t_, out);
    return;
  }
  if (config_.gyro_time_offset_s == 0) {
    process(in, out);
  } else {
    shift_gyro(in, out);
  }
}

// The gyro reading stamped t was measured at t + offset: the rate at an accelerometer time t is
// the gyro series interpolated at stamp t - offset, which for a negative offset lies in the
// future, so samples wait in a short queue until the gyro series reaches it.
void Navigator::shift_gyro(Input in, std::vector<Estimate>& out) {
  const double offset = config_.gyro_time_offset_s;
  gyro_history_.emplace_back(in.t, in.w);
  shift_queue_.push_back(in);
  auto rate_at = [&](double stamp) {
    if (stamp <= gyro_history_.front().first) return gyro_history_.front().second;
    for (std::size_t k = 1; k < gyro_history_.size(); ++k) {
      const auto& [t1, w1] = gyro_history_[k];
      if (stamp <= t1) {
        const auto& [t0, w0] = gyro_history_[k - 1];
        const double u = (stamp - t0) / (t1 - t0);
        return Eigen::Vector3d(w0 + u * (w1 - w0));
      }
    }
    return gyro_history_.back().second;
  };
  while (!shift_queue_.empty()) {
    Input& head = shift_queue_.front();
    const double stamp = head.t - offset;
    if (stamp > gyro_history_.back().first) break;  // not measured yet
    head.w = rate_at(stamp);
    const Input ready = head;
    shift_queue_.pop_front();
    process(ready, out);
    while (gyro_history_.size() > 2 && gyro_history_[1].first < stamp) gyro_history_.pop_front();
  }
}

// A reading with the filter's estimates taken out: the biases, the gyros' response to the spin and,
// turning, the centripetal acceleration of the accelerometers' offset from the tool axis and the
// tangential one of a spin that changes (stick-slip), whose rate of change the reading before gives.
ImuReading Navigator::reading(const Input& in, const Input* earlier) const {
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
  if (config_.samples_are_means && dt_nominal_ > 0) r.f = mean_to_instant(r.f, r.w, dt_nominal_);
  return r;
}

StillnessInput Navigator::detector_input(const Input& in) const {
  StillnessInput si;
  si.t = in.t;
  si.depth_m = in.depth;
  if (aligned_) {
    // The biases as the filter has them, but never beyond 3 sigma of what the sensor's figures
    // allow: a filter that has drifted off (no depth, a missed stop) must not blind the detector
    // to the very stops that would bring it back.
    // (refresh_detector_allowances keeps them, once per epoch.)
    si.f = in.f - detector_ba_;
    si.w_minus_expected = in.w - detector_bg_ - mech_.earth_rate_in_tool();
    si.extra_gyro_tol = aligned_gyro_tol_;
    si.g = g_;
  } else {
    si.f = in.f;
    si.w_minus_expected = in.w;
    si.extra_gyro_tol = kEarthRate + 3.0 * config_.gyro_bias_sd;
    si.g = config_.gravity.value_or(in.f.norm());
  }
  if (in.b && detector_.config().mode == StillnessConfig::Mode::Magnitude && config_.use_magnetometer && b0_) {
    si.field_deviation_uT = in.b->norm() - *b0_;
  }
  return si;
}

// Once aligned, at the filter's epochs (they change with the filter only): what the detector does
// not know of w_expected (3 sigma of the gyro bias estimate and of the earth rate's projection), and
// the biases it takes out.
void Navigator::refresh_detector_allowances() {
  const StateMatrix& p = kf_.covariance();
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
  detector_ba_ = bounded(ba_, kBiasSigmas * config_.accel_bias_sd);
  detector_bg_ = bounded(bg_, kBiasSigmas * config_.gyro_bias_sd);
}

void Navigator::refresh_noise(double dt) {
  if (!(dt > 0)) return;
  const double sigma_a = measured_sigma_a_.value_or(config_.accel_vrw / std::sqrt(dt));
  const double sigma_w = measured_sigma_w_.value_or(config_.gyro_arw / std::sqrt(dt));
  detector_.set_noise(std::max(sigma_a, kMinSigmaAccel), std::max(sigma_w, kMinSigmaGyro));
}

// Stated depth noise sets the depth test's limit from the start; unstated, the test waits for the
// noise the reports show, so that a noisy rig feed cannot hold off every still period meanwhile.
void Navigator::refresh_depth_tolerance() {
  double tol = std::numeric_limits<double>::infinity();
  if (config_.depth_noise_stated) {
    tol = std::max(config_.still_depth_tol_m, kDepthRangeSigmas * config_.depth_sd);
  } else if (measured_depth_sd_ || aligned_) {
    // Aligned without a measured noise: the reports never changed while still (exact depth).
    tol = std::max(config_.still_depth_tol_m, kDepthRangeSigmas * measured_depth_sd_.value_or(0.0));
  }
  detector_.set_depth_tolerance(tol);
}

// ---- never silent --------------------------------------------------------------------------------

// Before alignment: what the user did not state of the noise is read off the data, and a run that
// has not aligned after notice_after_s of data says why, once.
void Navigator::watch_before_alignment(const Input& in) {
  if (!first_t_) first_t_ = in.t;
  noise_floor_.add(in.t, in.f, in.w, in.depth);
  if (noise_floor_.blocks() != floor_blocks_used_) adopt_noise_floor();
  if (align_notice_given_ || in.t - *first_t_ < config_.notice_after_s) return;
  align_notice_given_ = true;
  notices_.push_back(format("not aligned after %.0f s of data: no still period of %.1f s found. ", in.t - *first_t_,
                            config_.min_still_s) +
                     failing_test_text());
}

bool Navigator::noise_known() const {
  if (detector_.config().mode != StillnessConfig::Mode::Magnitude) return true;
  return (config_.accel_noise_stated || measured_sigma_a_) && (config_.gyro_noise_stated || measured_sigma_w_);
}

void Navigator::adopt_noise_floor() {
  floor_blocks_used_ = noise_floor_.blocks();
  if (detector_.config().mode == StillnessConfig::Mode::Magnitude) {
    if (!config_.accel_noise_stated) measured_sigma_a_ = noise_floor_.accel_sd();
    if (!config_.gyro_noise_stated) measured_sigma_w_ = noise_floor_.gyro_sd();
  }
  if (!config_.depth_noise_stated && noise_floor_.depth_sd()) {
    measured_depth_sd_ = noise_floor_.depth_sd();
    depth_sd_ = std::max(config_.depth_sd, *measured_depth_sd_);
    refresh_depth_tolerance();
  }
}

// At alignment: the filter takes the measured noise where the user stated none and it exceeds the
// preset (a preset is a class of sensors, not this one), and the log says which noise set the limits.
void Navigator::adopt_measured_noise(double dt) {
  const double root_dt = std::sqrt(dt);
  if (measured_sigma_w_) noise_.gyro_arw = std::max(config_.gyro_arw, *measured_sigma_w_ * root_dt);
  if (measured_sigma_a_) noise_.accel_vrw = std::max(config_.accel_vrw, *measured_sigma_a_ * root_dt);
  if (!measured_sigma_a_ && !measured_sigma_w_ && !measured_depth_sd_) return;
  const auto said = [](bool measured) { return measured ? "measured" : "stated"; };
  const StillnessConfig& d = detector_.config();
  std::string text = format("noise per sample behind the stillness limits and the filter: accelerometer %.3g m/s^2 (", d.sigma_a) +
         said(measured_sigma_a_.has_value()) + format("), gyro %.3g deg/h (", d.sigma_w * kRadPerSecToDegPerHour) +
         said(measured_sigma_w_.has_value()) + ")";
  if (measured_depth_sd_) text += format(", depth %.3g m (measured)", *measured_depth_sd_);
  notices_.push_back(text);
}

// Aligned: a run without a stop for no_stop_notice_s says so once (the zero-velocity updates are
// what bounds the drift).
void Navigator::watch_for_stops(double t) {
  if (still_state_.still) {
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

// The detector's test that failed most often, at its closest approach to its limit, and the
// parameter that sets that limit.
std::string Navigator::failing_test_text() const {
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

// ---- processing ----------------------------------------------------------------------------------

void Navigator::process(const Input& in, std::vector<Estimate>& out) {
  refresh_noise(dt_nominal_);
  if (in.b) {
    last_b_ = *in.b;
    last_b_valid_ = true;
  }
  row_stats_.add(in.f, in.w, in.b, in.t);
  if (!aligned_) {
    before_alignment(in, out);
    return;
  }
  const ImuReading a = reading(*prev_, prev2_ ? &*prev2_ : nullptr), b = reading(in, &*prev_);
  if (prev2_) {
    const ImuReading before = reading(*prev2_);
    mech_.step(a, b, &before);
  } else {
    mech_.step(a, b);
  }
  if (in.depth) {
    // A new report: a value that changed, or the first row with depth after rows without (a rig
    // reports once a second; the logger holds the value or leaves the rows between empty).
    if (!latest_depth_ || *in.depth != *latest_depth_ || !prev_->depth) latest_depth_t_ = in.t;
    latest_depth_ = in.depth;
    last_depth_row_t_ = in.t;
    if (!have_depth0_) {
      // The first depth after alignment: the distance counts from the one at alignment, so this
      // reading is referred back by the distance travelled since then.
      depth0_ = *in.depth - mech_.state().s;
      have_depth0_ = true;
    }
  }

  const bool was_still = detector_.still();
  if (in.gyro_bad || in.accel_bad) {
    detector_.reset();
    still_state_ = StillnessState();
    still_state_.ended = was_still;
  } else {
    still_state_ = detector_.update(detector_input(in));
  }
  if (still_state_.started) {
    count("still_periods");
    ++zupt_periods_;
    mag_done_this_period_ = false;
    zaru_stats_.clear();
    mag_stats_.clear();
  }
  if (still_state_.still) {
    zaru_stats_.add(in.f, in.w, std::nullopt, in.t);
    if (in.b) mag_stats_.add(in.f, in.w, in.b, in.t);
  }
  const double kf_dt = 1.0 / config_.kf_rate_hz;
  const bool due = in.t - last_epoch_t_ >= kf_dt - 0.5 * dt_nominal_;
  const bool output_due = in.t >= next_output_t_ - 1e-9;
  if (due || output_due || still_state_.started || still_state_.ended) epoch(in, out);
  // A saturated (held) rate or a gap breaks the parabola: start again from a line.
  if (in.gyro_bad || (prev_ && in.t - prev_->t > config_.max_gap_s)) {
    prev2_.reset();
  } else {
    prev2_ = prev_;
  }
  prev_ = in;
}

void Navigator::before_alignment(const Input& in, std::vector<Estimate>& out) {
  watch_before_alignment(in);
  const StillnessInput si = detector_input(in);
  if (in.gyro_bad || in.accel_bad) {
    const bool was_still = detector_.still();
    detector_.reset();
    still_state_ = StillnessState();
    still_state_.ended = was_still;
  } else {
    still_state_ = detector_.update(si);
    // Noise neither stated nor measured yet: a still period cannot be judged, so none starts.
    if (!noise_known()) still_state_ = StillnessState();
  }
  if (still_state_.started) count("still_periods");
  if (still_state_.still) align_stats_.add(in.f, in.w, in.b, in.t);
  if (!still_state_.still) tally_.add(detector_.binding_check(si.extra_gyro_tol));
  const bool long_enough = align_stats_.duration() >= config_.align_s;
  const bool period_over = still_state_.ended && align_stats_.count() >= StillnessConfig::kMinWindowSamples;
  if (still_state_.still && long_enough) {
    align(in);
  } else if (period_over) {
    align(in);
  } else if (still_state_.ended) {
    align_stats_.clear();
  }
  prev_ = in;
  if (!aligned_) {
    emit(in.t, out);
  } else {
    // The first row of the navigation: the aligned state at this instant.
    next_output_t_ = in.t;
    epoch(in, out);
  }
}

void Navigator::align(const Input& in) {
  const StillStats stats = align_stats_;
  align_stats_.clear();
  const Eigen::Vector3d f = stats.mean_f(), w = stats.mean_w();
  const double fn = f.norm();
  // Accelerometers in g instead of m/s^2 read |f| ~ 1 at rest.
  const double expected_g = config_.gravity.value_or(9.80665);
  if (std::abs(fn - expected_g) > 0.2 * expected_g) {
    accel_in_g_ = true;
    accel_in_g_level_ = fn;
    count("accel_in_g");
    return;
  }
  accel_in_g_ = false;
  g_ = config_.gravity.value_or(fn);
  const bool mag = config_.use_magnetometer && stats.mag_count() >= StillnessConfig::kMinWindowSamples;
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  if (mag) {
    b = stats.mean_b();
    if (!b0_) b0_ = b.norm();
    if (!dip0_) dip0_ = dip_of(f, b);
  }

  double heading_sd = 0;
  const Eigen::Matrix3d c_bn = initial_attitude(f, w, b, mag, heading_sd);

  // The earth rate's horizontal part is taken along the frame's north. That is exact in a true
  // frame (gyrocompass, or declination given); in a magnetic frame without a declination, or a
  // relative one, it errs by the horizontal earth rate times sin(declination): 0.9 deg/h per 5 deg
  // of declination at 45 deg latitude, a gyro-bias-like error the zero-rate updates absorb.
  mech_ = Mechanization(earth_rate_ned(config_.latitude, 0.0), g_);
  // A drilling tool turns about its own axis and moves along it; a foot or a hand (no
  // lateral-velocity update, the GLRT detector) has no such axis: no offset from it, no turns of
  // 10^4 degrees about it, no magnetized string along it and no rate of penetration.
  drilling_tool_ = config_.lateral_velocity_update && detector_.config().mode == StillnessConfig::Mode::Magnitude;
  lever_model_ = config_.lever_arm_sd > 0 && drilling_tool_;
  mech_.set_lever_model(lever_model_);
  x_ = NavState();
  x_.q = Eigen::Quaterniond(c_bn).normalized();
  bg_.setZero();
  ba_.setZero();
  lever_.setZero();
  gyro_spin_.setZero();
  mag_axial_ = 0;
  const double dt = dt_nominal_ > 0 ? dt_nominal_ : 0.01;
  adopt_measured_noise(dt);
  const double sd_mean_f = mean_force_sd(stats, noise_.accel_vrw, dt);
  kf_.reset(initial_covariance(f, heading_sd, sd_mean_f));
  aligned_ = true;
  refresh_depth_tolerance();
  tally_.clear();
  last_still_t_ = in.t;
  // From now on the detector sees w less the expected earth rate and bias: its long means restart.
  detector_.restart_stretch();
  aligned_at_ = in.t;
  // The still period of the alignment is the tally's stop 0, not a connection.
  stop_started_t_ = std::numeric_limits<double>::infinity();
  lateral_excess_.setConstant(config_.nhc_sd * config_.nhc_sd);
  last_epoch_t_ = in.t;
  correction_.setZero();

  first_measurements(stats, sd_mean_f, dt);
  mag_done_this_period_ = true;
  zaru_stats_.clear();
  mag_stats_.clear();
  zupt_periods_ = 1;
  if (in.depth) {
    depth0_ = *in.depth;
    have_depth0_ = true;
  }
  integrals_.clear();
  mech_.begin(x_);
  refresh_detector_allowances();
  if (config_.smooth) {
    smoother_.store(StateMatrix::Identity(), 0.0, correction_, x_, bg_, ba_, kf_.covariance());
    correction_.setZero();
  }
}

// The attitude at alignment: tilt from the mean specific force, the heading from the earth rate
// (gyrocompass), a given azimuth, the magnetometer, or none (relative). Sets the azimuth reference
// and whether the magnetometer serves azimuth; heading_sd receives the heading's sigma.
Eigen::Matrix3d Navigator::initial_attitude(const Eigen::Vector3d& f, const Eigen::Vector3d& w,
                                            const Eigen::Vector3d& b, bool mag, double& heading_sd) {
  const double deg = std::numbers::pi / 180.0;
  heading_sd = 10.0 * deg;
  std::optional<Eigen::Matrix3d> c_bn;
  use_mag_ = false;
  if (config_.gyrocompass) {
    // The earth rate's horizontal part points at true north: the frame is true.
    c_bn = triad_attitude(f, w, 0.0);
    azimuth_reference_ = "true";
    use_mag_ = mag && config_.declination.has_value();
  } else if (config_.initial_azimuth) {
    c_bn = tilt_and_azimuth_attitude(f, *config_.initial_azimuth);
    azimuth_reference_ = "relative";
    heading_sd = std::max(config_.initial_azimuth_sd, 1e-6);
  } else if (mag) {
    c_bn = triad_attitude(f, b, field_azimuth());
    azimuth_reference_ = config_.declination ? "true" : "magnetic";
    use_mag_ = true;
  } else {
    c_bn = tilt_and_azimuth_attitude(f, 0.0);
    azimuth_reference_ = "relative";
    heading_sd = 1e-6;
  }
  if (!c_bn) {
    c_bn = tilt_and_azimuth_attitude(f, 0.0);
    azimuth_reference_ = "relative";
  }
  return *c_bn;
}

// The filter's covariance at alignment, before its first measurements.
StateMatrix Navigator::initial_covariance(const Eigen::Vector3d& f, double heading_sd, double sd_mean_f) const {
  const double deg = std::numbers::pi / 180.0;
  const double fn = f.norm();
  StateMatrix p0 = StateMatrix::Zero();
  const double tilt_sd = 2.0 * deg;
  p0.block<3, 3>(kAtt, kAtt).diagonal() << tilt_sd * tilt_sd, tilt_sd * tilt_sd, heading_sd * heading_sd;
  p0.block<3, 3>(kVel, kVel).diagonal().setConstant(1e-8);
  p0.block<3, 3>(kPos, kPos).diagonal().setConstant(1e-8);
  p0.block<3, 3>(kGyroBias, kGyroBias).diagonal().setConstant(config_.gyro_bias_sd * config_.gyro_bias_sd);
  p0.block<3, 3>(kAccelBias, kAccelBias).diagonal().setConstant(config_.accel_bias_sd * config_.accel_bias_sd);
  p0(kDistance, kDistance) = depth_sd_ * depth_sd_;
  if (lever_model_) p0.block<2, 2>(kLever, kLever).diagonal().setConstant(config_.lever_arm_sd * config_.lever_arm_sd);
  if (drilling_tool_) {
    p0(kGyroScale, kGyroScale) = config_.gyro_scale_sd * config_.gyro_scale_sd;
    p0.block<2, 2>(kGyroLeak, kGyroLeak).diagonal().setConstant(config_.gyro_misalignment_sd * config_.gyro_misalignment_sd);
    // g_s and g_a are each the mean of two independent elements.
    p0.block<2, 2>(kGyroG, kGyroG).diagonal().setConstant(0.5 * config_.gyro_g_sensitivity_sd * config_.gyro_g_sensitivity_sd);
    if (use_mag_) p0(kMagAxial, kMagAxial) = config_.mag_axial_bias_sd * config_.mag_axial_bias_sd;
  }
  if (config_.gravity) {
    p0(kGravity, kGravity) = config_.gravity_sd * config_.gravity_sd;
  } else {
    // |mean f| = g + u.b + the mean's noise along u (u = mean f / |mean f|, up in the tool frame),
    // and the bias estimate starts at zero: dg = -u.dba + noise. Without that noise term the
    // filter would hold g exact to the bias and its inclination sigma would be 2x too small.
    const Eigen::Vector3d up = f / fn;
    const double var_b = config_.accel_bias_sd * config_.accel_bias_sd;
    p0(kGravity, kGravity) = var_b + sd_mean_f * sd_mean_f;
    p0.block<1, 3>(kGravity, kAccelBias) = -var_b * up.transpose();
    p0.block<3, 1>(kAccelBias, kGravity) = -var_b * up;
  }
  return p0;
}

// The alignment's own means as the filter's first measurements.
void Navigator::first_measurements(const StillStats& stats, double sd_mean_f, double dt) {
  const Eigen::Vector3d f = stats.mean_f(), w = stats.mean_w();
  const double n = stats.count();
  // They shape P (tilt against the accelerometer biases, heading against the gyro biases) as the
  // data warrant.
  const double sd_w = std::max({stats.sample_sd_w(), noise_.gyro_arw / std::sqrt(dt)});
  {
    const Measurement<3> m = tilt(x_, ba_, g_, f, sd_mean_f);
    apply(kf_.update(m.r, m.h, m.noise));
    count("tilt_updates");
  }
  {
    const Measurement<3> m =
        zero_rate(x_, bg_, gyro_g_, mech_.earth_rate(), w, f, std::max(sd_w / std::sqrt(n), kMinMeanSdGyro));
    apply(kf_.update(m.r, m.h, m.noise));
    count("zero_rate_updates");
  }
  if (use_mag_) {
    mag_stats_ = stats;
    mag_done_this_period_ = false;
    magnetic_update();
  }
}

void Navigator::apply(const StateVector& dx) {
  feed_back(dx, x_, bg_, ba_, &lever_, &gyro_spin_, &mag_axial_, &gyro_g_);
  correction_ += dx;
  g_ -= dx[kGravity];
  mech_.set_gravity(g_);
}

double Navigator::field_azimuth() const { return config_.declination.value_or(0.0); }

void Navigator::epoch(const Input& in, std::vector<Estimate>& out) {
  // The full update of the two-rate mechanization, then the filter at the same instant.
  mech_.finish(x_, &integrals_);
  const StateMatrix phi = ErrorStateFilter::transition(integrals_, mech_.earth_rate());
  const double dt = integrals_.dt;
  ProcessNoise noise = noise_;
  if (!still_state_.still) {
    // The lateral innovations' excess beyond what a tool's lateral velocity can be: the velocity's
    // process noise carries it (isotropic, as the accelerometers' white noise).
    const double beyond = (lateral_excess_.array() - kLateralVelocityCap * kLateralVelocityCap).max(0.0).mean();
    noise.accel_vrw = std::sqrt(noise.accel_vrw * noise.accel_vrw + beyond * config_.kf_rate_hz);
  }
  kf_.predict(phi, dt, noise);
  integrals_.clear();
  last_epoch_t_ = in.t;
  correction_.setZero();

  if (still_state_.still) {
    const Measurement<3> m = zero_velocity(x_, config_.zupt_sd);
    apply(kf_.update(m.r, m.h, m.noise));
    count("zero_velocity_updates");
    still_updates(false);
  } else {
    if (still_state_.ended) {
      still_updates(true);
      late_stop_end();
    }
    if (config_.lateral_velocity_update) {
      Measurement<2> m = lateral_velocity(x_, config_.nhc_sd);
      // Covariance matching over the last kLateralMemoryS of motion: the innovations' mean square
      // beyond what the covariance explains is the tool's real lateral velocity (up to
      // kLateralVelocityCap; the rest is the velocity's process noise, epoch()).
      const Eigen::Matrix<double, kStates, 2> pht = kf_.covariance().lazyProduct(m.h.transpose());
      const Eigen::Vector2d excess = m.r.array().square() - (m.h.lazyProduct(pht)).diagonal().array();
      lateral_excess_ += std::min(1.0, 1.0 / (kLateralMemoryS * config_.kf_rate_hz)) * (excess - lateral_excess_);
      m.noise.diagonal() =
          lateral_excess_.cwiseMax(config_.nhc_sd * config_.nhc_sd).cwiseMin(kLateralVelocityCap * kLateralVelocityCap);
      apply(kf_.update(m.r, m.h, m.noise));
      count("lateral_velocity_updates");
    }
  }
  if (still_state_.started) stop_started_t_ = in.t;
  if (still_state_.still && in.t - stop_started_t_ >= config_.pipe_connection_s) {
    tally_update();
    stop_started_t_ = std::numeric_limits<double>::infinity();  // once per stop
  }
  if (latest_depth_ && have_depth0_ && in.t - last_depth_update_t_ >= config_.depth_interval_s - 0.5 * dt_nominal_) {
    // A report's age: the time since the last row that carried depth (depth only at connections,
    // or left empty between reports), plus how long a held value had stood then (a 1 Hz report held
    // on every row; at most kHeldDepthAge). A moving tool has gone on by its speed times that age,
    // which the update's sigma says.
    const double held = std::min(last_depth_row_t_ - latest_depth_t_, kHeldDepthAge);
    const double speed = x_.q.toRotationMatrix().col(2).dot(x_.v);
    const double stale_m = speed * (in.t - last_depth_row_t_ + held);
    const Measurement<1> m =
        along_hole_distance(x_, *latest_depth_ - depth0_, std::sqrt(depth_sd_ * depth_sd_ + stale_m * stale_m));
    apply(kf_.update(m.r, m.h, m.noise));
    count("depth_updates");
    last_depth_update_t_ = in.t;
  }
  // The minor steps go on from the corrected state.
  mech_.begin(x_);
  refresh_detector_allowances();
  watch_for_stops(in.t);
  if (config_.smooth) smoother_.store(phi, dt, correction_, x_, bg_, ba_, kf_.covariance());
  emit(in.t, out);
}

// A still period's end is seen late when the string speeds up slowly (its acceleration under the
// accelerometer noise): the zero-velocity updates held the velocity at zero while the tool already
// moved along its axis, at up to the rate of penetration. Said to the filter as velocity
// uncertainty along the axis at the end; depth, where there is some, takes it back out.
void Navigator::late_stop_end() {
  if (!(config_.rop_sd > 0) || !drilling_tool_) return;
  const Eigen::Vector3d axis = x_.q.toRotationMatrix().col(2);
  kf_.covariance().block<3, 3>(kVel, kVel) += (config_.rop_sd * config_.rop_sd) * axis * axis.transpose();
}

void Navigator::tally_update() {
  if (config_.pipe_tally_m.empty() || latest_depth_) return;  // measured depth, when there is one, wins
  if (!config_.pipe_tally_repeats && tally_stops_ >= config_.pipe_tally_m.size()) return;
  const double joint = config_.pipe_tally_m[config_.pipe_tally_repeats ? 0 : tally_stops_];
  ++tally_stops_;
  const Measurement<1> m = along_hole_distance(x_, tally_distance_ + joint,
                                               config_.pipe_tally_sd * std::sqrt(static_cast<double>(tally_stops_)));
  apply(kf_.update(m.r, m.h, m.noise));
  count("tally_updates");
  tally_distance_ += joint;
}

void Navigator::still_updates(bool period_end) {
  const double dt = dt_nominal_ > 0 ? dt_nominal_ : 0.01;
  const double n = zaru_stats_.count();
  if (n >= StillnessConfig::kMinWindowSamples && (period_end || zaru_stats_.duration() >= config_.zaru_interval_s)) {
    const double sd_w = std::max(zaru_stats_.sample_sd_w(), noise_.gyro_arw / std::sqrt(dt));
    const Measurement<3> m =
        zero_rate(x_, bg_, gyro_g_, mech_.earth_rate(), zaru_stats_.mean_w(), zaru_stats_.mean_f(), std::max(sd_w / std::sqrt(n), kMinMeanSdGyro));
    apply(kf_.update(m.r, m.h, m.noise));
    count("zero_rate_updates");
    if (config_.tilt_update) {
      const Measurement<3> t = tilt(x_, ba_, g_, zaru_stats_.mean_f(), mean_force_sd(zaru_stats_, noise_.accel_vrw, dt));
      apply(kf_.update(t.r, t.h, t.noise));
      count("tilt_updates");
    }
    zaru_stats_.clear();
  }
  if (use_mag_ && !mag_done_this_period_ && mag_stats_.mag_count() >= StillnessConfig::kMinWindowSamples &&
      (period_end || mag_stats_.duration() >= config_.mag_update_s)) {
    magnetic_update();
  }
  if (period_end) {
    zaru_stats_.clear();
    mag_stats_.clear();
  }
}

void Navigator::magnetic_update() {
  mag_done_this_period_ = true;
  // The gate sees the field as read, as the references learnt at alignment did; the heading, the
  // field less the axial bias the filter estimates.
  const Eigen::Vector3d raw_b = mag_stats_.mean_b(), f = mag_stats_.mean_f();
  const Eigen::Vector3d b = raw_b - mag_axial_ * Eigen::Vector3d::UnitZ();
  const double total = raw_b.norm(), dip = dip_of(f, raw_b);
  const double deg = std::numbers::pi / 180.0;
  if (std::abs(total - b0_.value_or(total)) > config_.field_tol_uT ||
      std::abs(dip - dip0_.value_or(dip)) > config_.dip_tol) {
    count("disturbed_field");
    last_field_warning_ = format("azimuth update skipped at a stop: field disturbed (|B| %.2f uT, dip %.2f deg; reference %.2f uT, ",
                                 total, dip / deg, b0_.value_or(total)) +
                          format("%.2f deg)", dip0_.value_or(dip) / deg);
    return;
  }
  const double bh = total * std::cos(dip);
  if (!(bh > 0)) return;
  const double n = mag_stats_.mag_count();
  const double sd_b = mag_stats_.sample_sd_b();
  const double sd = std::sqrt(sd_b * sd_b / n / (bh * bh) + config_.mag_heading_sd * config_.mag_heading_sd);
  const Measurement<1> m = magnetic_heading(x_, b, field_azimuth(), sd);
  apply(kf_.update(m.r, m.h, m.noise));
  count("azimuth_updates");
  last_field_warning_.clear();
}

// ---- output ------------------------------------------------------------------------------------

std::string Navigator::reason() const {
  if (saw_no_gyro_ && !saw_gyro_) return "no angular rate: strapdown needs gyros (wx, wy, wz)";
  if (accel_in_g_) {
    return format("accelerometers read |f| = %.3f at rest: they look like g units, strapdown needs m/s^2",
                  accel_in_g_level_);
  }
  if (!aligned_ && align_notice_given_) {
    // The row's reason is short (the attitude topic bounds it); the notice says the rest.
    return "not aligned: no still period (" + std::string(test_name(tally_.most_frequent().test)) + " too large)";
  }
  if (!aligned_) return "aligning: waiting for the first still period";
  return {};
}

void Navigator::fill_attitude(Estimate& e, const NavState& x, const StateMatrix& p) const {
  const Eigen::Matrix3d c_bn = x.q.toRotationMatrix();
  const AttitudeWithSigma a =
      attitude_with_sigma(c_bn, p.block<3, 3>(kAtt, kAtt), std::sin(kMinInclinationForToolfaceDeg * kDeg));
  e.inclination_deg = a.inclination * kRadToDeg;
  e.azimuth_deg = a.azimuth_valid ? wrap_deg_360(a.azimuth * kRadToDeg) : 0.0;
  e.gravity_toolface_deg = a.toolface_valid ? wrap_deg_360(a.toolface * kRadToDeg) : 0.0;
  e.inclination_sd_deg = a.inclination_sd * kRadToDeg;
  e.azimuth_sd_deg = a.azimuth_sd * kRadToDeg;
  // The toolface of a turning tool is known only as well as the instant it stands for (the row's
  // mean rate: e.rpm is filled before).
  e.toolface_sd_deg = std::hypot(a.toolface_sd * kRadToDeg, std::abs(e.rpm) * 6.0 * config_.time_tag_sd);
  e.valid = true;
  e.azimuth_valid = a.azimuth_valid;
  e.toolface_valid = a.toolface_valid;
  NavigationState nav;
  for (int k = 0; k < 3; ++k) {
    nav.position_m[k] = x.p[k];
    nav.velocity_mps[k] = x.v[k];
    nav.position_sd_m[k] = std::sqrt(std::max(0.0, p(kPos + k, kPos + k)));
    nav.velocity_sd_mps[k] = std::sqrt(std::max(0.0, p(kVel + k, kVel + k)));
  }
  nav.still = detector_.still();
  nav.zero_velocity_updates = zupt_periods_;
  nav.azimuth_reference = azimuth_reference_;
  e.navigation = nav;
}

Estimate Navigator::row(double t) const {
  Estimate e;
  e.estimator = "strapdown";
  e.t_start = last_row_t_;
  e.t_end = t;
  e.samples_used = static_cast<std::uint32_t>(row_stats_.count());
  if (row_stats_.count() > 0) {
    const Eigen::Vector3d f = row_stats_.mean_f();
    e.total_g = f.norm();
    // Rotation speed: the tool-axis rate less the earth rate's share (below 0.01 rpm anyway).
    e.rpm = row_stats_.mean_w().z() * 60.0 / (2.0 * std::numbers::pi);
    e.rotating = std::abs(e.rpm) > 1.0;
    if (row_stats_.mag_count() > 0) {
      const Eigen::Vector3d b = row_stats_.mean_b();
      e.total_b = b.norm();
      e.dip_deg = dip_of(f, b) * kRadToDeg;
    }
  }
  if (last_b_valid_) e.magnetic_toolface_deg = wrap_deg_360(std::atan2(-last_b_.y(), last_b_.x()) * kRadToDeg);
  const std::string why = reason();
  if (aligned_ && why.empty()) {
    fill_attitude(e, x_, kf_.covariance());
    std::string warning;
    if (t <= gap_warning_until_) warning = "time gap bridged by prediction only";
    if (!last_field_warning_.empty()) warning += (warning.empty() ? "" : "; ") + last_field_warning_;
    if (azimuth_reference_ == "relative" && !config_.initial_azimuth && !config_.gyrocompass) {
      warning += std::string(warning.empty() ? "" : "; ") + "no magnetometer and no initial_azimuth_deg: azimuth relative to the alignment heading";
    }
    e.reason = warning;
  } else {
    e.reason = why;
    NavigationState nav;
    nav.azimuth_reference = azimuth_reference_;
    e.navigation = nav;
  }
  for (double* v : {&e.inclination_deg, &e.azimuth_deg, &e.gravity_toolface_deg, &e.magnetic_toolface_deg, &e.rpm,
                    &e.inclination_sd_deg, &e.azimuth_sd_deg, &e.toolface_sd_deg, &e.dip_deg, &e.total_g, &e.total_b}) {
    if (!std::isfinite(*v)) {
      *v = 0;
      e.valid = e.azimuth_valid = e.toolface_valid = false;
      e.reason = "non-finite result";
    }
  }
  return e;
}

void Navigator::emit(double t, std::vector<Estimate>& out) {
  const double period = 1.0 / config_.output_rate_hz;
  if (!output_started_) {
    output_started_ = true;
    next_output_t_ = t + period;
    last_row_t_ = t;
    return;
  }
  if (t < next_output_t_ - 1e-9) return;
  Estimate e = row(t);
  count("rows");
  if (!e.valid) count("invalid_rows");
  next_output_t_ += period;
  if (next_output_t_ <= t) next_output_t_ = t + period;
  last_row_t_ = t;
  row_stats_.clear();
  if (config_.smooth) {
    PendingRow pr{std::move(e), std::nullopt};
    if (aligned_ && pr.row.valid && smoother_.size() > 0) pr.epoch = smoother_.size() - 1;
    pending_.push_back(std::move(pr));
  } else {
    out.push_back(std::move(e));
  }
}

void Navigator::flush(std::vector<Estimate>& out) {
  // Samples waiting for a later gyro reading: use the last one there is.
  while (!shift_queue_.empty()) {
    Input in = shift_queue_.front();
    shift_queue_.pop_front();
    in.w = gyro_history_.back().second;
    process(in, out);
  }
  // A recording that ends inside its first still period aligns on what it has.
  if (!aligned_ && detector_.still() && align_stats_.count() >= StillnessConfig::kMinWindowSamples && prev_) {
    const Input last = *prev_;
    align(last);
    if (aligned_) {
      next_output_t_ = last.t;
      epoch(last, out);
    }
  }
  // The stretch since the last row, if any.
  if (prev_ && last_t_ && row_stats_.count() > 0 && *last_t_ > last_row_t_) {
    next_output_t_ = std::min(next_output_t_, prev_->t);
    if (aligned_) {
      epoch(*prev_, out);
    } else {
      emit(prev_->t, out);
    }
  } else if (!prev_ && last_t_ && counters_["rows"] == 0 && counters_["samples"] > 0) {
    // Nothing navigable at all (no gyros, say): one row that says why.
    output_started_ = true;
    next_output_t_ = *last_t_;
    emit(*last_t_, out);
  }
  if (!config_.smooth) return;
  std::vector<std::optional<SmoothedEpoch>> smoothed(smoother_.size());
  std::vector<bool> wanted(smoother_.size(), false);
  for (const PendingRow& pr : pending_) {
    if (pr.epoch) wanted[*pr.epoch] = true;
  }
  smoother_.smooth(noise_, [&](std::size_t k, const SmoothedEpoch& e) {
    if (wanted[k]) smoothed[k] = e;
  });
  for (PendingRow& pr : pending_) {
    if (pr.epoch && smoothed[*pr.epoch]) {
      const std::string reason = pr.row.reason;
      const bool still = pr.row.navigation ? pr.row.navigation->still : false;
      const std::uint32_t zupts = pr.row.navigation ? pr.row.navigation->zero_velocity_updates : 0;
      fill_attitude(pr.row, smoothed[*pr.epoch]->state, smoothed[*pr.epoch]->p);
      pr.row.navigation->still = still;
      pr.row.navigation->zero_velocity_updates = zupts;
      pr.row.reason = reason;
    }
    out.push_back(std::move(pr.row));
  }
  pending_.clear();
}

}  // namespace plumb::strapdown
