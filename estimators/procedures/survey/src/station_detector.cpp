#include "plumb/survey/station_detector.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <limits>
#include <stdexcept>

#include "plumb/survey/stop_combiner.hpp"

namespace plumb::survey {

double PipeTally::depth_at(std::size_t stop) const {
  if (joint_lengths_m.empty()) throw std::invalid_argument("a pipe tally needs at least one joint length");
  double md = start_md_m;
  for (std::size_t k = 0; k < stop; ++k) md += joint_lengths_m[std::min(k, joint_lengths_m.size() - 1)];
  if (stop < corrections_m.size()) md += corrections_m[stop];
  return md;
}

StationDetector::StationDetector(DetectorOptions options, Sink sink, std::function<void(const std::string&)> note)
    : options_(std::move(options)), sink_(std::move(sink)), note_(std::move(note)) {
  if (!(options_.still_tolerance_m > 0) || !(options_.new_station_m > 0) || !(options_.max_depth_gap_s > 0) ||
      !(options_.min_still_s >= 0))
    throw std::invalid_argument("station detector: tolerances must be > 0");
  if (!std::isfinite(options_.depth_sd_m)) throw std::invalid_argument("station detector: depth sigma must be finite");
}

double StationDetector::depth_sd_m() const {
  if (options_.depth_sd_m >= 0) return options_.depth_sd_m;
  const auto measured = noise_.second_difference_sd();
  if (measured) return std::max(*measured, reported_sd_);
  return reported_sd_ > 0 ? reported_sd_ : std::numeric_limits<double>::quiet_NaN();
}

double StationDetector::still_tolerance_m() const {
  const double sd = depth_sd_m();
  return std::isfinite(sd) ? std::max(options_.still_tolerance_m, kStillSigmas * sd) : options_.still_tolerance_m;
}

void StationDetector::resume(double t, double md, std::size_t stations) {
  last_t_ = t;
  last_md_ = md;
  in_stop_ = true;
  stops_ = stations;
  counters_.stations = stations;
}

void StationDetector::add_depth(const DepthReport& d) {
  if (!std::isfinite(d.t_s) || !std::isfinite(d.depth_m)) return;
  // Reports arrive in order from one rig; a late one is put in its place.
  auto it = std::upper_bound(depth_.begin(), depth_.end(), d.t_s, [](double t, const DepthReport& r) { return t < r.t_s; });
  depth_.insert(it, d);
  noise_.add(d.t_s, d.depth_m);
  if (std::isfinite(d.sd_m)) reported_sd_ = std::max(reported_sd_, d.sd_m);
  process_ready(false);
}

void StationDetector::add_attitude(const Estimate& e, const std::string& tool_id) {
  ++counters_.windows;
  auto it = std::upper_bound(pending_.begin(), pending_.end(), e.t_end,
                             [](double t, const Pending& p) { return t < p.e.t_end; });
  pending_.insert(it, Pending{e, tool_id});
  process_ready(false);
}

void StationDetector::flush() {
  process_ready(true);
  close_stop();
}

void StationDetector::process_ready(bool all) {
  while (!pending_.empty()) {
    const Pending& p = pending_.front();
    // Without a tally, a window is decided once the depth after its end is known.
    // Windows wait for it at most depth_history_s of attitude time: a rig whose depth feed stopped
    // (or never started) must not make the survey hold every window forever (the long-run soak
    // test saw plumb-survey grow by 1 kB a second); such a window is decided now, without depth.
    if (!all && !options_.tally && (depth_.empty() || depth_.back().t_s < p.e.t_end) &&
        pending_.back().e.t_end - p.e.t_end <= options_.depth_history_s)
      break;
    decide(p);
    pending_.pop_front();
  }
  prune();
}

void StationDetector::prune() {
  // Windows arrive after their samples (a window's attitude after its last sample's depth), so the
  // depth of the last history_s is kept for the windows still to come, and whatever pending ones need.
  if (depth_.empty()) return;
  double keep_from = depth_.back().t_s - options_.depth_history_s;
  if (!pending_.empty()) keep_from = std::min(keep_from, pending_.front().e.t_start);
  keep_from -= options_.max_depth_gap_s + 1;
  while (depth_.size() > 2 && depth_[1].t_s < keep_from) depth_.pop_front();
}

void StationDetector::decide(const Pending& p) {
  const Estimate& e = p.e;
  if (e.t_end <= last_t_) {
    ++counters_.old_windows;
    return;
  }
  if (!e.valid) {
    ++counters_.invalid_windows;
    // Reasons carry numbers ("tilt 3.2 deg"): counted by their words before the first digit.
    std::string why = e.reason.empty() ? "no reason given" : e.reason;
    why = why.substr(0, std::min(why.find_first_of("0123456789:("), std::size_t{60}));
    while (!why.empty() && (why.back() == ' ' || why.back() == ',')) why.pop_back();
    ++counters_.invalid_reasons[why];
  } else if (e.rotating) {
    ++counters_.rotating_windows;
  }

  if (options_.tally) {
    // Without depth, stillness is all the attitude stream can tell: valid and not turning.
    const bool usable = e.valid && !e.rotating;
    // Stops are runs of usable windows.
    if (!usable) {
      in_stop_ = false;
      close_stop();
      return;
    }
    if (in_stop_) {
      if (stop_ && options_.whole_stop) stop_->windows.push_back(e);
      else ++counters_.same_stop_windows;
      return;
    }
    in_stop_ = true;
    stop_ = OpenStop{{e}, p.tool_id, options_.tally->depth_at(stops_), {}, options_.tally->sd_m};
    ++stops_;
    if (!options_.whole_stop) close_stop();
    return;
  }
  // With depth, any valid window will do: a dynamic estimator's window while the string turns off
  // bottom is as good a station as a static one.
  if (!e.valid) return;
  decide_with_depth(p);
}

void StationDetector::decide_with_depth(const Pending& p) {
  const Estimate& e = p.e;
  // The depth over the window (or the last min_still_s before its end, if longer): the last report
  // at or before its start, and every report inside it.
  const double gap = options_.max_depth_gap_s;
  const double start = std::min(e.t_start, e.t_end - options_.min_still_s);
  double lo = 1e300, hi = -1e300, sd = 0;
  bool before = false, after = false, moving = false;
  std::vector<double> values;
  // A rig may report only when the depth changes: the latest report at or before the start holds
  // however old it is.
  auto first = std::upper_bound(depth_.begin(), depth_.end(), start,
                                [](double t, const DepthReport& r) { return t < r.t_s; });
  if (first != depth_.begin()) --first;
  for (auto it = first; it != depth_.end(); ++it) {
    const DepthReport& d = *it;
    if (d.t_s > e.t_end + gap) break;
    if (d.t_s <= start) {
      // Only the latest report before the start counts; earlier ones are superseded.
      values.clear();
      lo = 1e300, hi = -1e300, moving = false;
    }
    // A report at or before the start (or within `gap` after it: a log that starts with the
    // window, at t = 0, has nothing before it), and one within `gap` of the end.
    if (d.t_s <= start + gap) before = true;
    if (d.t_s >= e.t_end - gap) after = true;
    lo = std::min(lo, d.depth_m);
    hi = std::max(hi, d.depth_m);
    moving = moving || (d.moving && d.t_s > start);
    sd = std::max(sd, d.sd_m);
    values.push_back(d.depth_m);
    if (d.t_s >= e.t_end) break;
  }
  if (values.empty() || !before || !after) {
    ++counters_.no_depth_windows;
    return;
  }
  const double tolerance = still_tolerance_m();
  // A navigator says itself whether the tool stands (a zero-velocity update in progress): its rows
  // of the slow start of drilling are not the stop's.
  const bool navigator_moving = e.navigation && !e.navigation->still;
  if (moving || navigator_moving || hi - lo > tolerance || creeping(e.t_end)) {
    ++counters_.moving_windows;
    // A noisy report can make one window of a stop look moving: the stop ends only when the
    // depth has left it.
    if (stop_ && moved_since(stop_->windows.back().t_end, stop_->md, e.t_end)) close_stop();
    return;
  }
  std::vector<double> sorted = values;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double md = sorted[sorted.size() / 2];
  const double md_sd = options_.depth_sd_m >= 0 ? options_.depth_sd_m : std::max(sd, std::isfinite(depth_sd_m()) ? depth_sd_m() : 0.0);
  if (stop_) {
    // The same stop while the depth stays where it stood.
    if (std::abs(md - stop_->md) <= tolerance && !moved_since(stop_->windows.back().t_end, stop_->md, e.t_start)) {
      if (options_.whole_stop) {
        stop_->windows.push_back(e);
        stop_->depths.insert(stop_->depths.end(), values.begin(), values.end());
      } else {
        ++counters_.same_stop_windows;
      }
      return;
    }
    close_stop();
  }
  if (last_md_ && std::abs(md - *last_md_) <= std::max(options_.new_station_m, tolerance)) {
    if (!moved_since(last_t_, *last_md_, e.t_start)) {
      ++counters_.same_stop_windows;
      return;
    }
    // The string moved and came back to the same depth: a resurvey of a station the survey has.
    ++counters_.repeat_stops;
    last_t_ = e.t_end;  // this stop is told once
    if (note_) {
      std::ostringstream o;
      o << "stop at " << md << " m repeats the last station's depth: not a new station (t " << e.t_end << " s)";
      note_(o.str());
    }
    return;
  }
  stop_ = OpenStop{{e}, p.tool_id, md, values, md_sd};
  if (!options_.whole_stop) close_stop();
}

void StationDetector::close_stop() {
  if (!stop_) return;
  OpenStop s = std::move(*stop_);
  stop_.reset();
  double md = s.md;
  if (!s.depths.empty()) {
    std::nth_element(s.depths.begin(), s.depths.begin() + static_cast<std::ptrdiff_t>(s.depths.size() / 2), s.depths.end());
    md = s.depths[s.depths.size() / 2];
  }
  take(s.windows, s.tool_id, md, s.md_sd);
}

double StationDetector::slope_span_s() const {
  // Long enough to tell the slowest drilling (kSlowestDrillingMps) from standing by 5 sigma of
  // the rate fitted through reports a second apart: 5 sd sqrt(12 / L^3) <= v.
  const double sd = depth_sd_m();
  const double needed = std::isfinite(sd) ? std::cbrt(300 * sd * sd / (kSlowestDrillingMps * kSlowestDrillingMps)) : 0.0;
  return std::clamp(needed, std::max(options_.min_still_s, kMinSlopeSpanS), kMaxSlopeSpanS);
}

bool StationDetector::creeping(double t_end) const {
  // A string drilling slowly stays within the depth tolerance over a few seconds of noisy reports;
  // the rate fitted over a longer span shows it. The report held at the span's start counts there.
  const double from = t_end - slope_span_s();
  auto it = std::upper_bound(depth_.begin(), depth_.end(), from, [](double t, const DepthReport& r) { return t < r.t_s; });
  if (it != depth_.begin()) --it;
  std::vector<std::pair<double, double>> points;
  for (; it != depth_.end() && it->t_s <= t_end; ++it) points.emplace_back(std::max(it->t_s, from), it->depth_m);
  if (points.size() < 4) return false;
  double st = 0, sd = 0;
  for (const auto& [t, d] : points) st += t, sd += d;
  const double n = static_cast<double>(points.size()), tm = st / n, dm = sd / n;
  double stt = 0, std_ = 0;
  for (const auto& [t, d] : points) stt += (t - tm) * (t - tm), std_ += (t - tm) * (d - dm);
  if (!(stt > 0)) return false;
  const double rate = std_ / stt;
  double sigma = depth_sd_m();
  if (!std::isfinite(sigma)) {
    double ss = 0;
    for (const auto& [t, d] : points) ss += std::pow(d - dm - rate * (t - tm), 2);
    sigma = std::sqrt(ss / (n - 2));
  }
  const double floor = options_.still_tolerance_m / slope_span_s();
  // 2.5 sigma: a standing window taken for moving costs only itself (the stop goes on without it).
  return std::abs(rate) > std::max(floor, 2.5 * sigma / std::sqrt(stt));
}

bool StationDetector::moved_since(double since, double md, double until) const {
  // Judged on the reports between `since` and `until`, in time order: reports of later motion
  // (offline, the depth runs ahead of the attitude) must not count. Reports already pruned, or
  // none (just resumed), say nothing: the stop goes on.
  const double tolerance = still_tolerance_m();
  // Two reports in a row away from `md`: one noisy report is not a move.
  const auto first = std::upper_bound(depth_.begin(), depth_.end(), since,
                                      [](double t, const DepthReport& r) { return t < r.t_s; });
  int away = 0;
  for (auto it = first; it != depth_.end() && it->t_s <= until; ++it) {
    if (it->moving) return true;
    away = std::abs(it->depth_m - md) > tolerance ? away + 1 : 0;
    if (away == 2) return true;
  }
  return false;
}

void StationDetector::take(const std::vector<Estimate>& windows, const std::string& tool_id, double md, double md_sd) {
  const CombinedAttitude c = combine_stop(windows);
  const Estimate& e = windows.back();
  Station s;
  s.t_s = c.t_end;
  s.tool_id = tool_id;
  s.source = e.estimator;
  s.md_m = md;
  s.md_sd_m = md_sd;
  s.inclination_deg = c.inclination_deg;
  // Not measured (NaN): a sigma of 0, the survey's "unknown"; near vertical, where the azimuth is
  // not measured, the previous station's azimuth (the position hardly depends on it there).
  s.inclination_sd_deg = std::isfinite(c.inclination_sd_deg) ? c.inclination_sd_deg : 0;
  s.magnetic_azimuth_deg = std::isfinite(c.azimuth_deg) ? c.azimuth_deg : last_azimuth_;
  s.azimuth_sd_deg = std::isfinite(c.azimuth_sd_deg) ? c.azimuth_sd_deg : 0;
  s.azimuth_valid = c.azimuth_valid;
  s.toolface_deg = c.toolface_deg;
  s.toolface_sd_deg = c.toolface_sd_deg;
  s.windows = static_cast<std::uint32_t>(c.windows);
  last_azimuth_ = s.magnetic_azimuth_deg;
  if (c.total_g > 0) s.total_g_mps2 = c.total_g;
  if (c.total_b > 0) {
    s.total_b_uT = c.total_b;
    s.dip_deg = c.dip_deg;
  }
  last_md_ = md;
  last_t_ = s.t_s;
  ++counters_.stations;
  counters_.combined_windows += c.windows;
  counters_.same_stop_windows += windows.size() - c.windows;
  sink_(s);
}

}  // namespace plumb::survey
