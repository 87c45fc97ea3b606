#include "plumb/survey/station_detector.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

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
  process_ready(false);
}

void StationDetector::add_attitude(const Estimate& e, const std::string& tool_id) {
  ++counters_.windows;
  auto it = std::upper_bound(pending_.begin(), pending_.end(), e.t_end,
                             [](double t, const Pending& p) { return t < p.e.t_end; });
  pending_.insert(it, Pending{e, tool_id});
  process_ready(false);
}

void StationDetector::flush() { process_ready(true); }

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
  if (!e.valid) ++counters_.invalid_windows;
  else if (e.rotating) ++counters_.rotating_windows;

  if (options_.tally) {
    // Without depth, stillness is all the attitude stream can tell: valid and not turning.
    const bool usable = e.valid && !e.rotating;
    // Stops are runs of usable windows; the first window of a run is the station.
    if (!usable) {
      in_stop_ = false;
      return;
    }
    if (in_stop_) {
      ++counters_.same_stop_windows;
      return;
    }
    in_stop_ = true;
    take(p, options_.tally->depth_at(stops_), options_.tally->sd_m);
    ++stops_;
    return;
  }

  // With depth, any valid window will do: a dynamic estimator's window while the string turns off
  // bottom is as good a station as a static one.
  if (!e.valid) return;
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
  if (moving || hi - lo > options_.still_tolerance_m) {
    ++counters_.moving_windows;
    return;
  }
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
  const double md = values[values.size() / 2];
  if (last_md_ && std::abs(md - *last_md_) <= options_.new_station_m) {
    if (!moved_since(e.t_start)) {
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
  take(p, md, sd);
}

bool StationDetector::moved_since(double until) const {
  // Judged on the reports between the last station and this window, in time order: reports of
  // later motion (offline, the depth runs ahead of the attitude) must not count. Reports already
  // pruned, or none (just resumed), say nothing: the stop goes on.
  const auto first = std::upper_bound(depth_.begin(), depth_.end(), last_t_,
                                      [](double t, const DepthReport& r) { return t < r.t_s; });
  for (auto it = first; it != depth_.end() && it->t_s <= until; ++it)
    if (it->moving || std::abs(it->depth_m - *last_md_) > options_.still_tolerance_m) return true;
  return false;
}

void StationDetector::take(const Pending& p, double md, double md_sd) {
  const Estimate& e = p.e;
  Station s;
  s.t_s = e.t_end;
  s.tool_id = p.tool_id;
  s.source = e.estimator;
  s.md_m = md;
  s.md_sd_m = md_sd;
  s.inclination_deg = e.inclination_deg;
  // Not measured (NaN): a sigma of 0, the survey's "unknown"; near vertical, where the azimuth is
  // not measured, the previous station's azimuth (the position hardly depends on it there).
  s.inclination_sd_deg = std::isfinite(e.inclination_sd_deg) ? e.inclination_sd_deg : 0;
  s.magnetic_azimuth_deg = std::isfinite(e.azimuth_deg) ? e.azimuth_deg : last_azimuth_;
  s.azimuth_sd_deg = std::isfinite(e.azimuth_sd_deg) ? e.azimuth_sd_deg : 0;
  s.azimuth_valid = e.azimuth_valid && std::isfinite(e.azimuth_deg);
  last_azimuth_ = s.magnetic_azimuth_deg;
  if (e.total_g > 0) s.total_g_mps2 = e.total_g;
  if (e.total_b > 0) {
    s.total_b_uT = e.total_b;
    s.dip_deg = e.dip_deg;
  }
  last_md_ = md;
  last_t_ = e.t_end;
  ++counters_.stations;
  sink_(s);
}

}  // namespace plumb::survey
