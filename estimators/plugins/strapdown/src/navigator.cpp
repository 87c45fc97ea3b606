#include "plumb/strapdown/navigator.hpp"

#include <cmath>
#include <optional>
#include <utility>

namespace plumb::strapdown {

Navigator::Navigator(const NavigatorConfig& config) { configure(config); }

void Navigator::configure(const NavigatorConfig& config) {
  config_ = config;
  reset();
}

void Navigator::reset() {
  counters_.clear();
  for (const char* name :
       {"samples", "accepted", "non_finite", "time_backwards", "repeated_time", "no_gyro", "gyro_saturated",
        "accel_saturated", "mag_unusable", "out_of_range", "gaps", "dropouts", "missing_samples", "repeated_samples", "accel_clipped", "gyro_clipped", "accel_in_g", "temperature_readings", "temperature_corrected", "still_periods",
        "zero_velocity_updates", "zero_rate_updates", "tilt_updates", "azimuth_updates", "disturbed_field",
        "lateral_velocity_updates", "axial_acceleration_updates", "depth_updates", "tally_updates", "stops_not_connections", "rows", "invalid_rows"}) {
    counters_[name] = 0;
  }
  checks_.reset(config_, counters_);
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
  lag_.reset(config_.stop_lag_s);
  unseen_.reset(config_);
  faults_.reset();
  ranges_.reset(config_);
  spin_.reset(config_);
  shocks_.reset();
  temperature_.reset(config_);
}

std::vector<std::string> Navigator::take_notices() {
  std::vector<std::string> notices = watch_.take_notices();
  for (std::string& n : unseen_.take_notices()) notices.push_back(std::move(n));
  for (std::string& n : faults_.take_notices()) notices.push_back(std::move(n));
  for (std::string& n : ranges_.take_notices()) notices.push_back(std::move(n));
  for (std::string& n : temperature_.take_notices()) notices.push_back(std::move(n));
  for (std::string& n : stops_.take_notices()) notices.push_back(std::move(n));
  return notices;
}

// ---- input -------------------------------------------------------------------------------------

void Navigator::push(const Sample& s, std::vector<Estimate>& out) {
  Input in;
  const InputChecks::Verdict verdict = checks_.accept(s, in, counters_);
  // still_detector=auto: the magnitude test leans on |B|. A stream whose first sample has no
  // field gets the GLRT, as use_magnetometer=0 does.
  if (verdict.first_without_field) watch_.use_glrt_without_field();
  if (verdict.gap) {
    rows_.note_gap(s.t);
    // A still tool that loses a few seconds of samples is judged across the gap by the readings on
    // either side (its window keeps the last ones before it, and depth's range spans it): forgetting
    // would end the stop, and every stop a dropout broke cost the late end's allowance (the end 2-14 %
    // of MD off instead of 0.03-0.07 % with 1.5 dropouts a minute). After a long gap, it is a new run.
    if (!watch_.still() || !(verdict.lost_dt > 0) || verdict.lost_dt > kStillAcrossGapS) watch_.forget();
  }
  if (verdict.repeated) faults_.repeat(s.t, verdict.same_stamp);
  if (verdict.lost_dt > 0) faults_.lost(s.t, verdict.lost_dt, checks_.dt_nominal(), counters_);
  if (verdict.navigable) {
    ranges_.seen(in);
    temperature_.correct(in, counters_);
  }
  if (!verdict.navigable) {
    if (!aligned_ && checks_.last_t()) emit(*checks_.last_t(), out);
    return;
  }
  if (config_.gyro_time_offset_s == 0) {
    process(in, out);
    return;
  }
  checks_.queue(in);
  while (const std::optional<Input> ready = checks_.next_ready()) process(*ready, out);
}

// ---- processing ----------------------------------------------------------------------------------

// Before alignment every reading goes straight on (the first rows must not wait); once aligned,
// the detector judges each reading as it comes, and the filter takes it stop_lag_s later with the
// decision as known then (stillness_lag.hpp).
void Navigator::process(const Input& in, std::vector<Estimate>& out) {
  watch_.refresh_noise(checks_.dt_nominal());
  if (!aligned_) {
    rows_.add_reading(in);
    before_alignment(in, out);
    return;
  }
  const StillnessState decision = watch_.aligned(in, filter_, aligner_.field().total_uT);
  if (!(lag_.lag_s() > 0)) {
    navigate(in, decision, out);
    return;
  }
  lag_.push(in, decision);
  while (const std::optional<StillnessLag::Entry> ready = lag_.pop_ready()) navigate(ready->reading, ready->still, out);
}

void Navigator::navigate(Input in, const StillnessState& still, std::vector<Estimate>& out) {
  rows_.add_reading(in);
  // Samples lost before this one: the step bridges them, and the epoch's noise says what they cost.
  const double step_dt = in.t - prev_->t, dt_nominal = checks_.dt_nominal();
  const bool gap = checks_.lost_samples(step_dt);
  // The mechanization steps between the readings' instants, and what integrates a rate over the
  // step takes theirs (a stamp may be behind the one before); everything else keeps the stamps.
  const double prev_instant = clock_.instant();
  const double instant = clock_.next(in.t, step_dt, dt_nominal, checks_.dt_jitter(), gap, checks_.ordered_by_seq());
  const double instant_dt = instant - prev_instant;
  // An axial gyro at its range: the spin the magnetometers or the accelerometers see stands in for
  // its rate.
  std::optional<ClippedSpin::Spin> spin;
  if (filter_.drilling_tool() && ((in.clipped & kAxialGyroClipped) != 0 || in.gyro_bad) && !gap) {
    spin = spin_.through(in, *prev_, instant_dt, filter_.mechanization().tool_to_nav(), filter_.gravity());
    if (spin) in.w.z() = spin->rate;
  } else {
    spin_.read();
  }
  if (gap) rows_.note_gap(in.t);
  Input at = in, from = *prev_;
  at.t = instant;
  from.t = prev_instant;
  std::optional<Input> from2 = prev2_;
  if (from2) from2->t = prev2_instant_;
  // (A drilling tool's. A foot's gaps, a few samples within a stride, are bridged as before: with
  // the allowance the short walk of tests/data/walks ended 0.176 m off instead of 0.138 m.)
  if (gap && filter_.drilling_tool()) {
    bridge_gap(from, at, in, dt_nominal);
  } else {
    if (filter_.drilling_tool() && shocks_.starts(in)) shocks_.start(filter_.mechanization().state());
    filter_.step(from, at, from2 ? &*from2 : nullptr, config_.samples_are_means, checks_.dt_nominal());
    if (spin) filter_.turn_about_axis(spin->turn);
    if (shocks_.ends(in)) {
      const Eigen::Matrix3d c_bn = filter_.mechanization().tool_to_nav();
      const ShockRebound::Shift back = shocks_.end(filter_.mechanization().state(), c_bn.col(2));
      filter_.shift_motion(back.dv, back.dp);
    }
  }
  faults_.observe(in, step_dt, dt_nominal);
  // At this reading's attitude: the filter's state is the last full update's, degrees behind a
  // turning tool.
  if (in.clipped != 0 || spin)
    ranges_.integrate(in, instant_dt, filter_.mechanization().tool_to_nav(), spin ? spin_.source_name() : nullptr);
  if (in.depth) {
    stops_.take_depth(in.t, *in.depth, prev_->depth.has_value(), filter_, still.still, watch_.depth_sd());
    unseen_.note_depth(in.t);
  }
  still_state_ = still;
  stops_.follow(in, still_state_, counters_);
  const double kf_dt = 1.0 / config_.kf_rate_hz;
  const bool due = in.t - last_epoch_t_ >= kf_dt - 0.5 * checks_.dt_nominal();
  // Not inside a clipped shock: its velocity is taken back at its end (shock_rebound.hpp), and the
  // lateral-velocity updates would read it as attitude meanwhile.
  const bool in_shock = shocks_.open();
  if (((due || rows_.output_due(in.t)) && !in_shock) || still_state_.started || still_state_.ended) epoch(in, out);
  // A saturated (held) or followed rate or a gap breaks the parabola: start again from a line.
  if (in.gyro_bad || spin || (prev_ && in.t - prev_->t > config_.max_gap_s)) {
    prev2_.reset();
  } else {
    prev2_ = prev_;
    prev2_instant_ = prev_instant;
  }
  prev_ = std::move(in);
}

// A drilling tool's step across lost samples (from and at: the readings either side at their
// instants; in: the reading after the gap as it came).
void Navigator::bridge_gap(const Input& from, const Input& at, const Input& in, double dt_nominal) {
  const Eigen::Matrix3d c_bn = filter_.mechanization().tool_to_nav();
  faults_.bridge(*prev_, in, dt_nominal, c_bn);
  // Its velocity across the axis is vibration, whose mean over a gap is nothing: the instant's,
  // held through the gap, would move it by that velocity times the gap.
  const Eigen::Vector3d v = filter_.mechanization().state().v;
  const Eigen::Vector3d across = v - c_bn.col(2) * c_bn.col(2).dot(v);
  // Through the gap in steps of the nominal interval, on readings made up (stream_faults.hpp).
  std::vector<Input> made_up = StreamFaults::gap_readings(
      from, at, c_bn, dt_nominal, Eigen::Vector3d(0.0, 0.0, -filter_.gravity()), filter_.accel_bias(),
      faults_.cross_rate());
  for (std::size_t k = 1; k + 1 < made_up.size(); ++k)
    filter_.as_read(made_up[k], &made_up[k - 1], config_.samples_are_means, dt_nominal);
  for (std::size_t k = 1; k < made_up.size(); ++k)
    filter_.step(made_up[k - 1], made_up[k], nullptr, config_.samples_are_means, dt_nominal);
  filter_.shift_motion(-across, -across * (at.t - from.t));
  // The field across the axis says how far the tool turned about it over the gap.
  if (const std::optional<double> turn = unseen_turn_across_gap(*prev_, in, c_bn, filter_.mechanization().tool_to_nav())) {
    filter_.turn_about_axis(faults_.axial_turn_seen(*turn, in.b->head<2>().norm(), in.b->norm()));
  }
}

void Navigator::before_alignment(const Input& in, std::vector<Estimate>& out) {
  if (in.depth) unseen_.note_depth(in.t);
  still_state_ = watch_.before_alignment(in, aligner_.field().total_uT);
  if (in.depth)
    stops_.take_depth(in.t, *in.depth, prev_ && prev_->depth.has_value(), filter_, still_state_.still, watch_.depth_sd());
  if (still_state_.started) count("still_periods");
  if (aligner_.take(in, still_state_)) align(in);
  prev_ = in;
  clock_.restart(in.t);
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
  // A drill string speeds up over seconds; a foot's stance lasts a fraction of one, and would vanish.
  // Measured depth sees a slow start itself (the depth test): no lag, no stop's end taken back
  // (with rig depth the lag cost MEMS 0.41 -> 0.50 deg of worst attitude).
  lag_.reset(drilling_tool && !watch_.depth_seen() ? config_.stop_lag_s : 0.0);
  stops_.set_stop_lag(lag_.lag_s());
  const double dt = checks_.dt_nominal() > 0 ? checks_.dt_nominal() : 0.01;
  watch_.adopt_measured_noise(dt, filter_.noise());
  const double sd_mean_f = mean_force_sd(coarse->stats, filter_.noise().accel_vrw, dt);
  filter_.reset_covariance(aligner_.initial_covariance(coarse->stats.mean_f(), coarse->heading_sd, sd_mean_f,
                                                       watch_.depth_sd(), filter_.lever_model(), drilling_tool));
  aligned_ = true;
  unseen_.at_alignment(in.t, drilling_tool);
  watch_.on_aligned(in.t, lag_.lag_s() > 0);
  last_epoch_t_ = in.t;
  filter_.clear_correction();
  stops_.at_alignment(filter_, coarse->stats, sd_mean_f, dt, aligner_.use_mag(), aligner_.field(), in.depth,
                      counters_);
  filter_.begin_steps();
  watch_.refresh_allowances(filter_, in.t);
  if (config_.smooth) {
    rows_.store_alignment(filter_);
    filter_.clear_correction();
  }
}

void Navigator::epoch(const Input& in, std::vector<Estimate>& out) {
  // The full update of the two-rate mechanization, then the filter at the same instant.
  // Without depth or a tally, a stop may be a slide the sensors cannot see.
  UnseenMotionNoise unseen =
      unseen_.at_epoch(filter_.state().q.toRotationMatrix().col(2), still_state_, in.t, in.t - last_epoch_t_);
  ranges_.add_to(unseen);
  faults_.add_to(unseen);
  if (const double spin_variance = spin_.take_variance(); spin_variance > 0)
    unseen.turn.head<3>() += std::sqrt(spin_variance) * filter_.mechanization().tool_to_nav().col(2);
  const FilterState::Prediction prediction =
      filter_.predict(temperature_.widen(faults_.widen(stops_.process_noise(filter_.noise(), still_state_,
                                                                            filter_.drilling_tool()),
                                                       in.t - last_epoch_t_),
                                         in.t - last_epoch_t_),
                      unseen);
  last_epoch_t_ = in.t;
  stops_.at_epoch(filter_, prediction, still_state_, in.t, checks_.dt_nominal(), watch_.depth_sd(), watch_.depth_tolerance(),
                  aligner_.use_mag(), aligner_.field(), counters_);
  // The minor steps go on from the corrected state.
  filter_.begin_steps();
  watch_.refresh_allowances(filter_, in.t);
  watch_.watch_for_stops(in.t, still_state_.still);
  if (config_.smooth) rows_.store_epoch(filter_, prediction);
  emit(in.t, out);
}

// ---- output ------------------------------------------------------------------------------------

std::string Navigator::reason() const {
  if (checks_.no_gyro_at_all()) return "no angular rate: strapdown needs gyros (wx, wy, wz)";
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
  c.still = aligned_ ? still_state_.still : watch_.still();
  c.stops = stops_.stops();
  c.azimuth_reference = aligner_.azimuth_reference();
  c.field_warning = stops_.field_warning();
  c.motion_warning = unseen_.row_warning();
  c.range_warning = ranges_.row_warning();
  if (std::string temperature = temperature_.row_warning(); !temperature.empty())
    c.range_warning += (c.range_warning.empty() ? "" : "; ") + temperature;
  c.measured_instant_sd_s = clock_.instant_sd(checks_.dt_nominal(), checks_.dt_jitter(), checks_.ordered_by_seq());
  if (aligner_.use_mag() && aligner_.field().dip) {
    // Magnetic north lies at the declination in a true frame, at 0 in a magnetic one.
    const double dip = *aligner_.field().dip, d = config_.declination.value_or(0.0);
    c.field_direction_n = Eigen::Vector3d(std::cos(dip) * std::cos(d), std::cos(dip) * std::sin(d), std::sin(dip));
  }
  return c;
}

void Navigator::emit(double t, std::vector<Estimate>& out) {
  if (rows_.due(t)) {
    rows_.emit(t, row_context(), counters_, out);
    ranges_.row_done();
  }
}

void Navigator::flush(std::vector<Estimate>& out) {
  // Samples waiting for a later gyro reading: use the last one there is.
  while (const std::optional<Input> waiting = checks_.next_waiting()) process(*waiting, out);
  // The readings the filter has not reached yet, with the decisions known at the end.
  while (const std::optional<StillnessLag::Entry> waiting = lag_.pop_any()) navigate(waiting->reading, waiting->still, out);
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
  const std::optional<double> last_t = checks_.last_t();
  if (prev_ && last_t && rows_.readings_since_row(*last_t)) {
    rows_.due_by(prev_->t);
    if (aligned_) {
      epoch(*prev_, out);
    } else {
      emit(prev_->t, out);
    }
  } else if (!prev_ && last_t && counters_["rows"] == 0 && counters_["samples"] > 0) {
    // Nothing navigable at all (no gyros, say): one row that says why.
    rows_.start_at(*last_t);
    emit(*last_t, out);
  }
  if (config_.smooth) rows_.flush_smoothed(row_context(), out);
}

}  // namespace plumb::strapdown
