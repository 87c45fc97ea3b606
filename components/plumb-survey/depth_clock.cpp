#include "depth_clock.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace plumb::survey_component {
namespace {

clock_sync::DepthStillnessOptions depth_still_options(const DepthClockOptions& o) {
  clock_sync::DepthStillnessOptions d;
  d.tolerance_m = o.still_tolerance_m;
  return d;
}

std::uint64_t clock_us(double s) { return static_cast<std::uint64_t>(std::llround(std::abs(s) * 1e6)); }

}  // namespace

void check_depth_clock_options(const DepthClockOptions& o) {
  if (o.offset_s && !std::isfinite(*o.offset_s))
    throw std::invalid_argument("--depth-clock-offset: a finite number of seconds, not " + std::to_string(*o.offset_s));
  if (o.drift_ppm && !(std::abs(*o.drift_ppm) <= 1000))
    throw std::invalid_argument("--depth-clock-drift-ppm: within -1000..1000 ppm, not " + std::to_string(*o.drift_ppm));
}

DepthClock::DepthClock(DepthClockOptions options) : options_(options), depth_still_(depth_still_options(options)) {
  check_depth_clock_options(options_);
  if (options_.offset_s || options_.drift_ppm) {
    clock_sync::ClockEstimate e;
    e.offset_s = options_.offset_s.value_or(0);
    e.drift = options_.drift_ppm.value_or(0) * 1e-6;
    given_ = e;
  }
}

void DepthClock::add_depth(const survey::DepthReport& d) {
  if (!given_) {
    if (d.t_s <= last_depth_t_) {
      ++out_of_order_;
      return;
    }
    last_depth_t_ = d.t_s;
    if (auto run = depth_still_.add(d.t_s, d.depth_m)) fit_.add_depth_run(*run);
  }
  held_.push_back(d);
  if (held_.size() > options_.max_held) {
    held_.pop_front();
    ++dropped_;
  }
}

void DepthClock::add_sensor(const Sample& s) {
  if (given_ || s.t <= last_sensor_t_) return;
  last_sensor_t_ = s.t;
  if (auto run = sensor_still_.add_sample(s.t, s.f, s.w, (s.flags & flags::kHasGyro) != 0)) fit_.add_sensor_run(*run);
}

const std::optional<clock_sync::ClockEstimate>& DepthClock::alignment() {
  if (given_) return given_;
  fit_.set_coverage(depth_still_.first_t(), depth_still_.settled_until(), sensor_still_.first_t(),
                    sensor_still_.settled_until());
  return fit_.estimate();
}

std::vector<survey::DepthReport> DepthClock::take_aligned() {
  std::vector<survey::DepthReport> out;
  const auto& a = alignment();
  if (!a) return out;
  out.reserve(held_.size());
  for (auto d : held_) {
    d.t_s = a->sensor_time(d.t_s);
    out.push_back(d);
  }
  held_.clear();
  return out;
}

std::string DepthClock::describe() {
  if (given_) {
    char line[200];
    std::snprintf(line, sizeof line, "depth clock given: %.6f s %s the sensors', drift %.3f ppm (not estimated)",
                  std::abs(given_->offset_s), given_->offset_s >= 0 ? "ahead of" : "behind", given_->drift * 1e6);
    return line;
  }
  const auto& a = alignment();
  std::string line = clock_sync::describe(a, fit_.depth_runs(), fit_.sensor_runs());
  if (!a) line += ": " + fit_.why_not();
  return line;
}

std::vector<std::pair<std::string, std::uint64_t>> DepthClock::counters() {
  const auto& a = alignment();
  const double offset = a ? a->offset_s : 0, drift = a ? a->drift : 0;
  return {{"depth_clock_state", given_ ? 2u : (a ? 1u : 0u)},  // 0 waiting, 1 estimated, 2 given
          {"depth_clock_ahead_us", offset > 0 ? clock_us(offset) : 0},
          {"depth_clock_behind_us", offset < 0 ? clock_us(offset) : 0},
          {"depth_clock_sd_us", a ? clock_us(a->offset_sd_s) : 0},
          {"depth_clock_fast_ppb", drift > 0 ? clock_us(drift * 1e3) : 0},
          {"depth_clock_slow_ppb", drift < 0 ? clock_us(drift * 1e3) : 0},
          {"depth_clock_drift_sd_ppb", a ? clock_us(a->drift_sd * 1e3) : 0},
          {"depth_clock_stops", a ? a->matched : 0},
          {"depths_held", held_.size()},
          {"depths_dropped_unaligned", dropped_}};
}

}  // namespace plumb::survey_component
