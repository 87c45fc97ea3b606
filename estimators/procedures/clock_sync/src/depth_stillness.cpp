#include "plumb/clock_sync/depth_stillness.hpp"

#include <algorithm>
#include <cmath>

namespace plumb::clock_sync {
namespace {

// Where the steady motion of `reports` (those at least `away` from `level`) reaches `level`, or
// nothing when they do not show steady motion toward or from it.
std::optional<double> depth_line_meets(const std::vector<std::pair<double, double>>& reports, double level, double away) {
  if (reports.empty()) return std::nullopt;
  // Centred: stamps of 1.7e9 s squared would leave no digits for a minute's spread.
  const double t0 = reports.front().first;
  double n = 0, st = 0, sd = 0, stt = 0, std_ = 0;
  for (const auto& [t_abs, d_abs] : reports)
    if (std::abs(d_abs - level) >= away) {
      const double t = t_abs - t0, d = d_abs - level;
      n += 1;
      st += t;
      sd += d;
      stt += t * t;
      std_ += t * d;
    }
  if (n < 3) return std::nullopt;
  const double tm = st / n, dm = sd / n, var = stt / n - tm * tm;
  if (var <= 0) return std::nullopt;
  const double slope = (std_ / n - tm * dm) / var;
  if (std::abs(slope) < 1e-4) return std::nullopt;  // 0.36 m/h: not a string on the move
  return t0 + tm - dm / slope;
}

}  // namespace

DepthStillness::DepthStillness(DepthStillnessOptions options) : options_(options) {}

void DepthStillness::start_piece(double t_s, double depth_m, double prev_t, bool after_motion) {
  piece_ = DepthPiece{};
  piece_.reports.assign(1, {t_s, depth_m});
  piece_.prev_t = prev_t;
  piece_.after_motion = after_motion;
  piece_.lo = piece_.hi = depth_m;
  // Only the motion since the last stand: its reports are not on the line.
  for (const auto& r : recent_)
    if (r.first > motion_since_t_) piece_.before.push_back(r);
}

double DepthStillness::median_of(const DepthPiece& p) const {
  std::vector<double> depths;
  depths.reserve(p.reports.size());
  for (const auto& r : p.reports) depths.push_back(r.second);
  std::nth_element(depths.begin(), depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2), depths.end());
  return depths[depths.size() / 2];
}

StillRun DepthStillness::placed(const DepthPiece& p, const std::vector<std::pair<double, double>>& following) const {
  const double level = median_of(p), half = 0.5 * options_.tolerance_m;
  const auto& r = p.reports;
  std::size_t first = 0, last = r.size() - 1;
  while (first < last && std::abs(r[first].second - level) > half) ++first;
  while (last > first && std::abs(r[last].second - level) > half) --last;
  const double before = first == 0 ? p.prev_t : r[first - 1].first;
  const double after = last + 1 == r.size() ? p.after_t : r[last + 1].first;
  StillRun run{0.5 * (before + r[first].first), 0.5 * (r[last].first + after)};
  // Both ends from steady motion, or neither: one end placed each way would leave a lag in the midpoint.
  const double away = 2 * options_.tolerance_m;
  const auto begin = depth_line_meets(p.before, level, away);
  const auto end = depth_line_meets(following, level, away);
  if (begin && end && *begin < *end && std::abs(*begin - run.begin_s) < options_.fit_span_s &&
      std::abs(*end - run.end_s) < options_.fit_span_s)
    run = StillRun{*begin, *end};
  return run;
}

std::optional<StillRun> DepthStillness::settle(double t_s, bool force) {
  if (!leaving_) return std::nullopt;
  if (!force && t_s - leaving_->after_t < options_.fit_span_s + 2 * options_.min_still_s) return std::nullopt;
  // The next stand, if one has begun, is not the motion after this one.
  if (piece_.duration_s() >= options_.min_still_s)
    while (!after_.empty() && after_.back().first >= piece_.reports.front().first) after_.pop_back();
  std::optional<StillRun> run;
  if (leaving_->after_motion) run = placed(*leaving_, after_);
  leaving_.reset();
  after_.clear();
  return run;
}

std::optional<StillRun> DepthStillness::add(double t_s, double depth_m) {
  ++reports_;
  std::optional<StillRun> run;
  if (leaving_) {
    // The reports after an ended stand, until fit_span_s of them are in (or a gap, or the next stand).
    const bool gap = t_s - last_t_ > options_.max_gap_s;
    if (!gap) after_.emplace_back(t_s, depth_m);
    run = settle(t_s, gap);
  }
  recent_.emplace_back(t_s, depth_m);
  std::size_t old = 0;
  while (old < recent_.size() && recent_[old].first < t_s - options_.fit_span_s - 2 * options_.min_still_s) ++old;
  recent_.erase(recent_.begin(), recent_.begin() + static_cast<std::ptrdiff_t>(old));
  if (!have_ || t_s - last_t_ > options_.max_gap_s) {
    // Nothing is known before this report: a stand starting here has no known beginning, and one
    // that was waiting has no known end.
    if (!have_) first_t_ = t_s;
    have_ = true;
    last_t_ = t_s;
    pending_.reset();
    recent_.assign(1, {t_s, depth_m});
    motion_since_t_ = t_s;
    start_piece(t_s, depth_m, t_s, false);
    return run;
  }
  const double lo = std::min(piece_.lo, depth_m), hi = std::max(piece_.hi, depth_m);
  // The margin keeps two-decimal readings exactly the tolerance apart (999.99, 1000.01) inside it.
  if (hi - lo <= options_.tolerance_m * (1 + 1e-9) + 1e-9) {
    piece_.lo = lo;
    piece_.hi = hi;
    last_t_ = t_s;
    // A string standing for days keeps a bounded record: the ends are what matter.
    if (piece_.reports.size() < 200000) piece_.reports.emplace_back(t_s, depth_m);
    return run;
  }
  // The depth left the piece.
  piece_.after_t = t_s;
  const bool still = piece_.duration_s() >= options_.min_still_s;
  if (still && pending_ && std::abs(median_of(piece_) - median_of(*pending_)) <= 0.5 * options_.tolerance_m) {
    // The same stand, broken by a noisy report.
    pending_->reports.insert(pending_->reports.end(), piece_.reports.begin(), piece_.reports.end());
    pending_->after_t = t_s;
  } else {
    if (pending_) {
      // That stand is over: its end is placed once the reports after it are in.
      if (auto earlier = settle(t_s, true)) run = earlier;
      leaving_ = std::move(pending_);
      after_.assign(piece_.reports.begin(), piece_.reports.end());
      after_.emplace_back(t_s, depth_m);
    }
    pending_.reset();
    if (still) {
      // A new stand: the motion after the one before ends here.
      if (leaving_) {
        while (!after_.empty() && after_.back().first >= piece_.reports.front().first) after_.pop_back();
        if (auto earlier = settle(t_s, true)) run = earlier;
      }
      pending_ = piece_;
    }
  }
  if (still) motion_since_t_ = piece_.reports.back().first;
  const double prev = last_t_;
  last_t_ = t_s;
  start_piece(t_s, depth_m, prev, true);
  return run;
}

}  // namespace plumb::clock_sync
