#include "plumb/clock_sync/clock_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace plumb::clock_sync {
namespace {

struct ClockCandidate {
  double offset_s = 0;
  std::size_t count = 0;
  double abs_sum_s = 0;
  long score = 0;  // matched - runs the other stream should have seen and did not
};

struct ClockCoverage {
  double depth_from, depth_until, sensor_from, sensor_until;
};

struct ClockPair {
  double sensor_mid = 0, depth_mid = 0;
};

bool clock_durations_agree(const StillRun& a, const StillRun& b, const ClockFitOptions& o) {
  const double longer = std::max(a.duration_s(), b.duration_s());
  return std::abs(a.duration_s() - b.duration_s()) <= std::max(o.duration_tolerance_s, o.duration_tolerance_rel * longer);
}

// The depth run whose midpoint is nearest `predicted` within `tolerance` and whose duration agrees.
const StillRun* clock_nearest_depth(const std::deque<StillRun>& depth, const StillRun& sensor, double predicted,
                                    double tolerance, const ClockFitOptions& o) {
  const auto first = std::lower_bound(depth.begin(), depth.end(), predicted - tolerance,
                                      [](const StillRun& r, double t) { return r.mid_s() < t; });
  const StillRun* best = nullptr;
  for (auto it = first; it != depth.end() && it->mid_s() <= predicted + tolerance; ++it)
    if (clock_durations_agree(*it, sensor, o) &&
        (best == nullptr || std::abs(it->mid_s() - predicted) < std::abs(best->mid_s() - predicted)))
      best = &*it;
  return best;
}

ClockCandidate clock_score(double offset_s, const std::deque<StillRun>& depth, const std::deque<StillRun>& sensor,
                           const ClockFitOptions& o, const ClockCoverage& cover) {
  ClockCandidate c{offset_s, 0, 0, 0};
  const double margin = o.match_tolerance_s;
  std::size_t missed = 0;
  for (const auto& s : sensor) {
    if (const StillRun* d = clock_nearest_depth(depth, s, s.mid_s() + offset_s, o.match_tolerance_s, o)) {
      ++c.count;
      c.abs_sum_s += std::abs(d->mid_s() - s.mid_s() - offset_s);
    } else if (s.begin_s + offset_s - margin > cover.depth_from && s.end_s + offset_s + margin < cover.depth_until) {
      ++missed;  // the depth was watching and stood still nowhere near
    }
  }
  for (const auto& d : depth) {
    if (d.begin_s - offset_s - margin <= cover.sensor_from || d.end_s - offset_s + margin >= cover.sensor_until) continue;
    bool seen = false;
    for (const auto& s : sensor)
      if (std::abs(d.mid_s() - s.mid_s() - offset_s) <= o.match_tolerance_s && clock_durations_agree(d, s, o)) seen = true;
    if (!seen) ++missed;
  }
  c.score = static_cast<long>(c.count) - static_cast<long>(missed);
  return c;
}

}  // namespace

double ClockEstimate::sensor_time(double t_depth_s) const {
  return (t_depth_s - offset_s + drift * t_ref_s) / (1 + drift);
}

std::string describe(const std::optional<ClockEstimate>& e, std::size_t depth_runs, std::size_t sensor_runs) {
  char line[320];
  if (!e) {
    std::snprintf(line, sizeof line, "depth clock not aligned yet (%zu depth and %zu sensor still runs)", depth_runs,
                  sensor_runs);
    return line;
  }
  std::snprintf(line, sizeof line,
                "depth clock %.3f s %s the sensors' (sd %.3f s) at sensor time %.1f s, drift %.1f ppm (sd %.1f ppm), "
                "from %zu stops matched (%zu depth, %zu sensor still runs)",
                std::abs(e->offset_s), e->offset_s >= 0 ? "ahead of" : "behind", e->offset_sd_s, e->t_ref_s,
                e->drift * 1e6, e->drift_sd * 1e6, e->matched, depth_runs, sensor_runs);
  return line;
}

ClockFit::ClockFit(ClockFitOptions options) : options_(options) {}

void ClockFit::add_depth_run(const StillRun& r) {
  depth_.push_back(r);
  if (depth_.size() > options_.max_runs) depth_.pop_front();
  dirty_ = true;
}

void ClockFit::set_coverage(double depth_from_s, double depth_until_s, double sensor_from_s, double sensor_until_s) {
  depth_from_ = depth_from_s;
  depth_until_ = depth_until_s;
  sensor_from_ = sensor_from_s;
  sensor_until_ = sensor_until_s;
}

void ClockFit::add_sensor_run(const StillRun& r) {
  sensor_.push_back(r);
  if (sensor_.size() > options_.max_runs) sensor_.pop_front();
  dirty_ = true;
}

const std::optional<ClockEstimate>& ClockFit::estimate() {
  if (dirty_) compute();
  dirty_ = false;
  return estimate_;
}

void ClockFit::compute() {
  estimate_.reset();
  const auto& o = options_;
  if (depth_.empty() || sensor_.empty()) {
    why_not_ = "no stop seen yet on " + std::string(depth_.empty() ? "the depth" : "the sensors");
    return;
  }
  // Every offset at which two runs coincide: where the cross-correlation of the still/moving series can peak.
  const ClockCoverage cover{depth_from_, depth_until_, sensor_from_, sensor_until_};
  std::vector<ClockCandidate> candidates;
  for (const auto& d : depth_)
    for (const auto& s : sensor_)
      if (clock_durations_agree(d, s, o)) candidates.push_back(clock_score(d.mid_s() - s.mid_s(), depth_, sensor_, o, cover));
  std::size_t best_count = 0;
  for (const auto& c : candidates) best_count = std::max(best_count, c.count);
  if (best_count < o.min_matched) {
    why_not_ = std::to_string(best_count) + " stop(s) matched so far (" + std::to_string(o.min_matched) + " needed)";
    return;
  }
  long best_score = -1000000;
  for (const auto& c : candidates)
    if (c.count >= o.min_matched) best_score = std::max(best_score, c.score);
  // Offsets that explain the stops as well: one cluster is one answer, two are an ambiguity.
  std::vector<ClockCandidate> top;
  for (const auto& c : candidates)
    if (c.count >= o.min_matched && c.score == best_score) top.push_back(c);
  std::sort(top.begin(), top.end(), [](const ClockCandidate& a, const ClockCandidate& b) { return a.offset_s < b.offset_s; });
  std::size_t clusters = 1;
  ClockCandidate best = top.front();
  for (std::size_t i = 1; i < top.size(); ++i) {
    if (top[i].offset_s - top[i - 1].offset_s > 2 * o.match_tolerance_s) ++clusters;
    if (top[i].count > best.count || (top[i].count == best.count && top[i].abs_sum_s < best.abs_sum_s)) best = top[i];
  }
  best_count = best.count;
  if (clusters > 1) {
    char line[200];
    std::snprintf(line, sizeof line, "%zu offsets explain %zu stops each (e.g. %.1f s and %.1f s): waiting for a stop "
                  "that tells them apart", clusters, best_count, top.front().offset_s, top.back().offset_s);
    why_not_ = line;
    return;
  }

  // Offset and drift by least squares on the matched midpoints, re-matched with the fit until stable.
  ClockEstimate e;
  e.offset_s = best.offset_s;
  double sd = 0.5 * o.match_tolerance_s;
  double tolerance = o.match_tolerance_s;
  for (int iteration = 0; iteration < 5; ++iteration) {
    std::vector<ClockPair> pairs;
    for (const auto& s : sensor_)
      if (const StillRun* d = clock_nearest_depth(depth_, s, s.mid_s() + e.offset_at(s.mid_s()), tolerance, o))
        pairs.push_back({s.mid_s(), d->mid_s()});
    if (pairs.size() < o.min_matched) break;
    double t_ref = 0;
    for (const auto& p : pairs) t_ref += p.sensor_mid;
    t_ref /= static_cast<double>(pairs.size());
    // Normal equations of y = offset + drift x, x = t_sensor - t_ref, with the prior drift = 0 +- drift_prior_sd.
    double n = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
    for (const auto& p : pairs) {
      const double x = p.sensor_mid - t_ref, y = p.depth_mid - p.sensor_mid;
      n += 1;
      sx += x;
      sxx += x * x;
      sy += y;
      sxy += x * y;
    }
    const double prior = (sd * sd) / (o.drift_prior_sd * o.drift_prior_sd);
    const double a11 = n, a12 = sx, a22 = sxx + prior;
    const double det = a11 * a22 - a12 * a12;
    const double offset = (a22 * sy - a12 * sxy) / det;
    const double drift = (a11 * sxy - a12 * sy) / det;
    double rss = 0;
    for (const auto& p : pairs) {
      const double r = p.depth_mid - p.sensor_mid - offset - drift * (p.sensor_mid - t_ref);
      rss += r * r;
    }
    rss += prior * drift * drift;
    // n midpoints and the prior against two unknowns.
    const double dof = std::max(1.0, n - 1);
    e.residual_sd_s = std::sqrt(rss / dof);
    sd = std::max(e.residual_sd_s, o.timing_floor_s);
    e.offset_s = offset;
    e.drift = drift;
    e.t_ref_s = t_ref;
    e.matched = pairs.size();
    // Covariance: sd^2 (A'A)^-1 with the prior's weight at this sd.
    const double prior_now = (sd * sd) / (o.drift_prior_sd * o.drift_prior_sd);
    const double det_now = n * (sxx + prior_now) - sx * sx;
    // The sd itself comes from few residuals: Student's t widens it (its variance is dof / (dof - 2)).
    const double widen = dof > 2 ? std::sqrt(dof / (dof - 2)) : 2.0;
    e.offset_sd_s = widen * sd * std::sqrt((sxx + prior_now) / det_now);
    e.drift_sd = widen * sd * std::sqrt(n / det_now);
    tolerance = std::min(o.match_tolerance_s, std::max(5 * sd, 0.5));
  }
  if (e.matched < o.min_matched) {
    why_not_ = "the matched stops did not hold together in the fit";
    return;
  }
  e.candidates_tied = 0;
  estimate_ = e;
  why_not_.clear();
}

}  // namespace plumb::clock_sync
