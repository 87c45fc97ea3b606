#include "plumb/strapdown/input_checks.hpp"

#include <cmath>
#include <cstddef>

namespace plumb::strapdown {

namespace {

// Magnetometer readings below this are "no magnetometer" (a logger without one writes zeros).
constexpr double kNoFieldUT = 1e-3;
// A reading this close to the range sits at it (the last code of a converter is one step short).
constexpr double kAtRange = 0.999;

}  // namespace

void InputChecks::reset(const NavigatorConfig& config, Counters& counters) {
  config_ = config;
  samples_counter_ = &counters["samples"];
  accepted_counter_ = &counters["accepted"];
  last_t_.reset();
  last_good_w_.reset();
  last_good_f_.reset();
  shift_queue_.clear();
  gyro_history_.clear();
  dt_nominal_ = 0;
  dt_jitter_ = 0;
  last_seq_ = 0;
  seq_counts_ = false;
  saw_gyro_ = saw_no_gyro_ = false;
}

InputChecks::Verdict InputChecks::accept(const Sample& s, InputReading& in, Counters& counters) {
  Verdict verdict;
  ++*samples_counter_;
  const bool has_gyro = (s.flags & flags::kHasGyro) != 0;
  if ((s.flags & flags::kNotFinite) != 0 || !std::isfinite(s.t) || !s.f.allFinite() ||
      (has_gyro && !s.w.allFinite())) {
    count(counters, "non_finite");
    return verdict;
  }
  if ((s.flags & flags::kTimeBackwards) != 0 || (last_t_ && s.t < *last_t_)) {
    if (!behind_within_jitter(s)) {
      count(counters, "time_backwards");
      return verdict;
    }
    // The next sample of the stream, stamped early by the jitter (1 ms at 400 Hz puts 4 % of the
    // stamps behind the one before): its place is its seq's, its instant the stamp clock's.
    count(counters, "stamps_behind");
  }
  if (last_t_ && s.t == *last_t_) {
    count(counters, "repeated_time");
    verdict.repeated = verdict.same_stamp = true;
    return verdict;
  }
  if (seq_counts_ && s.seq == last_seq_ && s.f == last_f_ && s.w == last_w_) {
    count(counters, "repeated_samples");
    verdict.repeated = true;
    return verdict;
  }
  if ((s.flags & flags::kOutOfRange) != 0) {
    count(counters, "out_of_range");
    return verdict;
  }
  in.t = s.t;
  if (!has_gyro) {
    // Rows keep coming (invalid, saying why); the sample itself cannot be navigated.
    count(counters, "no_gyro");
    saw_no_gyro_ = true;
    last_t_ = s.t;
    return verdict;
  }
  saw_gyro_ = true;
  // The range on any axis, flagged or not (a file carries no flags): the part beyond is unknown.
  for (int i = 0; i < 3; ++i) {
    if (std::abs(s.f[i]) >= kAtRange * config_.accel_range) in.clipped |= static_cast<std::uint8_t>(1u << i);
    if (std::abs(s.w[i]) >= kAtRange * config_.gyro_range) in.clipped |= static_cast<std::uint8_t>(8u << i);
  }
  if ((in.clipped & 7u) != 0) count(counters, "accel_clipped");
  if ((in.clipped & 56u) != 0) count(counters, "gyro_clipped");
  in.w = s.w;
  if ((s.flags & flags::kGyroSaturated) != 0) {
    count(counters, "gyro_saturated");
    if (!last_good_w_) return verdict;
    in.w = *last_good_w_;
    in.gyro_bad = true;
  } else {
    last_good_w_ = s.w;
  }
  in.f = s.f;
  if ((s.flags & flags::kAccelSaturated) != 0) {
    count(counters, "accel_saturated");
    if (!last_good_f_) return verdict;
    in.f = *last_good_f_;
    in.accel_bad = true;
  } else {
    last_good_f_ = s.f;
  }
  if ((s.flags & flags::kMagSaturated) != 0 || !s.b.allFinite()) {
    count(counters, "mag_unusable");
  } else if (const double b_norm = s.b.norm(); b_norm > kNoFieldUT) {
    in.b = s.b;
    in.b_norm = b_norm;
  }
  // (No bx,by,bz columns, or a tool without magnetometers.)
  verdict.first_without_field = !last_t_ && !in.b;
  if ((s.flags & flags::kHasDepth) != 0 && std::isfinite(s.depth_m)) in.depth = s.depth_m;
  if ((s.flags & (flags::kHasTemperature | flags::kTemperatureOutOfRange)) == flags::kHasTemperature &&
      std::isfinite(s.temp_c))
    in.temp_c = s.temp_c;
  if (last_t_) {
    const double dt = s.t - *last_t_;
    const bool lost = lost_samples(dt);
    if (lost) verdict.lost_dt = dt;
    if (dt > config_.max_gap_s) {
      count(counters, "gaps");
      verdict.gap = true;
    } else if (!lost) {
      // (Samples lost do not make the interval longer.)
      if (dt_nominal_ > 0) dt_jitter_ += 0.01 * (1.25 * std::abs(dt - dt_nominal_) - dt_jitter_);
      dt_nominal_ = dt_nominal_ > 0 ? 0.99 * dt_nominal_ + 0.01 * dt : dt;
    }
  }
  last_t_ = s.t;
  // (A stream whose samples all carry the same seq, 0 say, does not count them.)
  if (last_t_ && s.seq != last_seq_) seq_counts_ = true;
  last_seq_ = s.seq;
  last_f_ = s.f;
  last_w_ = s.w;
  ++*accepted_counter_;
  verdict.navigable = true;
  return verdict;
}

// Only where the stream's seq counts its samples (a file's rows are counted in the order the logger
// wrote them) can a stamp behind the one before be placed: by its seq, the very next one; and only a
// stamp that the jitter measured so far explains, as for a step that lost nothing.
bool InputChecks::behind_within_jitter(const Sample& s) const {
  return last_t_ && seq_counts_ && s.seq == last_seq_ + 1 && dt_jitter_ > 0 &&
         std::abs(s.t - *last_t_ - dt_nominal_) <= kJitterSigmas * dt_jitter_;
}

void InputChecks::queue(const InputReading& in) {
  gyro_history_.emplace_back(in.t, in.w);
  shift_queue_.push_back(in);
}

// The rate at an accelerometer time t is the gyro series interpolated at stamp t - offset, which
// for a negative offset lies in the future.
Eigen::Vector3d InputChecks::rate_at(double stamp) const {
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
}

std::optional<InputReading> InputChecks::next_ready() {
  if (shift_queue_.empty()) return std::nullopt;
  InputReading& head = shift_queue_.front();
  const double stamp = head.t - config_.gyro_time_offset_s;
  if (stamp > gyro_history_.back().first) return std::nullopt;  // not measured yet
  head.w = rate_at(stamp);
  const InputReading ready = head;
  shift_queue_.pop_front();
  while (gyro_history_.size() > 2 && gyro_history_[1].first < stamp) gyro_history_.pop_front();
  return ready;
}

std::optional<InputReading> InputChecks::next_waiting() {
  if (shift_queue_.empty()) return std::nullopt;
  InputReading in = shift_queue_.front();
  shift_queue_.pop_front();
  in.w = gyro_history_.back().second;
  return in;
}

}  // namespace plumb::strapdown
