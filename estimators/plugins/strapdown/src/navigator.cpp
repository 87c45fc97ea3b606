#include "plumb/strapdown/navigator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plumb::strapdown {

namespace {

// Magnetometer readings below this are "no magnetometer" (a logger without one writes zeros).
constexpr double kNoFieldUT = 1e-3;

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
  aligned_ = false;
  prev_.reset();
  prev2_.reset();
  last_epoch_t_ = 0;
  still_state_ = StillnessState();
  watch_.reset(config_);
  aligner_.reset(config_);
  filter_.reset(config_);
  stops_.reset(config_);
  rows_.reset(config_);
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
  if (!last_t_ && !in.b) watch_.use_glrt_without_field();
  if ((s.flags & flags::kHasDepth) != 0 && std::isfinite(s.depth_m)) in.depth = s.depth_m;
  if (last_t_) {
    const double dt = s.t - *last_t_;
    if (dt > config_.max_gap_s) {
      count("gaps");
      rows_.note_gap(s.t);
      watch_.forget();
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

// ---- processing ----------------------------------------------------------------------------------

void Navigator::process(const Input& in, std::vector<Estimate>& out) {
  watch_.refresh_noise(dt_nominal_);
  rows_.add_reading(in);
  if (!aligned_) {
    before_alignment(in, out);
    return;
  }
  const ImuReading a = filter_.corrected(*prev_, config_.samples_are_means, dt_nominal_);
  const ImuReading b = filter_.corrected(in, config_.samples_are_means, dt_nominal_);
  if (prev2_) {
    const ImuReading before = filter_.corrected(*prev2_, config_.samples_are_means, dt_nominal_);
    filter_.step(a, b, &before);
  } else {
    filter_.step(a, b, nullptr);
  }
  if (in.depth) stops_.take_depth(in.t, *in.depth, prev_->depth.has_value(), filter_);
  still_state_ = watch_.aligned(in, filter_, aligner_.field().total_uT);
  stops_.follow(in, still_state_, counters_);
  const double kf_dt = 1.0 / config_.kf_rate_hz;
  const bool due = in.t - last_epoch_t_ >= kf_dt - 0.5 * dt_nominal_;
  if (due || rows_.output_due(in.t) || still_state_.started || still_state_.ended) epoch(in, out);
  // A saturated (held) rate or a gap breaks the parabola: start again from a line.
  if (in.gyro_bad || (prev_ && in.t - prev_->t > config_.max_gap_s)) {
    prev2_.reset();
  } else {
    prev2_ = prev_;
  }
  prev_ = in;
}

void Navigator::before_alignment(const Input& in, std::vector<Estimate>& out) {
  still_state_ = watch_.before_alignment(in, aligner_.field().total_uT);
  if (still_state_.started) count("still_periods");
  if (aligner_.take(in, still_state_)) align(in);
  prev_ = in;
  if (!aligned_) {
    emit(in.t, out);
  } else {
    // The first row of the navigation: the aligned state at this instant.
    rows_.due_at(in.t);
    epoch(in, out);
  }
}

// The alignment's steps, each in its part: the coarse attitude, the filter's start with the noise
// the watch measured, the watch's limits for an aligned filter, the alignment's means as the first
// measurements, and the smoother's first epoch.
void Navigator::align(const Input& in) {
  const std::optional<Aligner::Coarse> coarse = aligner_.coarse(counters_);
  if (!coarse) return;
  // A drilling tool turns about its own axis and moves along it; a foot or a hand (no
  // lateral-velocity update, the GLRT detector) has no such axis: no offset from it, no turns of
  // 10^4 degrees about it, no magnetized string along it and no rate of penetration.
  const bool drilling_tool = config_.lateral_velocity_update && watch_.mode() == StillnessConfig::Mode::Magnitude;
  filter_.start(coarse->c_bn, coarse->g, config_.latitude, drilling_tool, config_.lever_arm_sd > 0 && drilling_tool);
  const double dt = dt_nominal_ > 0 ? dt_nominal_ : 0.01;
  watch_.adopt_measured_noise(dt, filter_.noise());
  const double sd_mean_f = mean_force_sd(coarse->stats, filter_.noise().accel_vrw, dt);
  filter_.reset_covariance(aligner_.initial_covariance(coarse->stats.mean_f(), coarse->heading_sd, sd_mean_f,
                                                       watch_.depth_sd(), filter_.lever_model(), drilling_tool));
  aligned_ = true;
  watch_.on_aligned(in.t);
  last_epoch_t_ = in.t;
  filter_.clear_correction();
  stops_.at_alignment(filter_, coarse->stats, sd_mean_f, dt, aligner_.use_mag(), aligner_.field(), in.depth,
                      counters_);
  filter_.begin_steps();
  watch_.refresh_allowances(filter_);
  if (config_.smooth) {
    rows_.store_alignment(filter_);
    filter_.clear_correction();
  }
}

void Navigator::epoch(const Input& in, std::vector<Estimate>& out) {
  // The full update of the two-rate mechanization, then the filter at the same instant.
  const FilterState::Prediction prediction = filter_.predict();
  last_epoch_t_ = in.t;
  stops_.at_epoch(filter_, still_state_, in.t, dt_nominal_, watch_.depth_sd(), aligner_.use_mag(), aligner_.field(),
                  counters_);
  // The minor steps go on from the corrected state.
  filter_.begin_steps();
  watch_.refresh_allowances(filter_);
  watch_.watch_for_stops(in.t, still_state_.still);
  if (config_.smooth) rows_.store_epoch(filter_, prediction);
  emit(in.t, out);
}

// ---- output ------------------------------------------------------------------------------------

std::string Navigator::reason() const {
  if (saw_no_gyro_ && !saw_gyro_) return "no angular rate: strapdown needs gyros (wx, wy, wz)";
  if (aligner_.accel_in_g()) {
    return format("accelerometers read |f| = %.3f at rest: they look like g units, strapdown needs m/s^2",
                  aligner_.accel_in_g_level());
  }
  if (!aligned_) {
    const std::string why = watch_.not_aligned_reason();
    return why.empty() ? "aligning: waiting for the first still period" : why;
  }
  return {};
}

RowContext Navigator::row_context() const {
  RowContext c;
  c.aligned = aligned_;
  c.why = reason();
  c.filter = &filter_;
  c.still = watch_.still();
  c.stops = stops_.stops();
  c.azimuth_reference = aligner_.azimuth_reference();
  c.field_warning = stops_.field_warning();
  return c;
}

void Navigator::emit(double t, std::vector<Estimate>& out) {
  if (rows_.due(t)) rows_.emit(t, row_context(), counters_, out);
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
  if (!aligned_ && aligner_.can_align_at_end(watch_.still()) && prev_) {
    const Input last = *prev_;
    align(last);
    if (aligned_) {
      rows_.due_at(last.t);
      epoch(last, out);
    }
  }
  // The stretch since the last row, if any.
  if (prev_ && last_t_ && rows_.readings_since_row(*last_t_)) {
    rows_.due_by(prev_->t);
    if (aligned_) {
      epoch(*prev_, out);
    } else {
      emit(prev_->t, out);
    }
  } else if (!prev_ && last_t_ && counters_["rows"] == 0 && counters_["samples"] > 0) {
    // Nothing navigable at all (no gyros, say): one row that says why.
    rows_.start_at(*last_t_);
    emit(*last_t_, out);
  }
  if (config_.smooth) rows_.flush_smoothed(filter_.noise(), row_context(), out);
}

}  // namespace plumb::strapdown
