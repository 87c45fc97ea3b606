#include "plumb/strapdown/depth_trend.hpp"

#include <algorithm>
#include <cmath>

namespace plumb::strapdown {

void DepthTrend::Sums::add(double px, double py, double sign) {
  n += sign;
  x += sign * px;
  y += sign * py;
  xx += sign * px * px;
  xy += sign * px * py;
  yy += sign * py * py;
}

void DepthTrend::clear() {
  older_.clear();
  recent_.clear();
  older_sums_ = recent_sums_ = Sums{};
  last_t_ = judged_t_ = -1e300;
  judged_moving_ = false;
}

void DepthTrend::add(double t, double depth) {
  if (t - last_t_ < (depth == last_depth_ ? 1.0 : 0.1)) return;
  last_t_ = t;
  last_depth_ = depth;
  drop_before(t);
  if (older_.empty() && recent_.empty()) {
    t0_ = t;
    d0_ = depth;
    older_sums_ = recent_sums_ = Sums{};
  }
  const double x = t - t0_, y = depth - d0_;
  recent_.emplace_back(x, y);
  recent_sums_.add(x, y, 1);
  // The sums are kept near the window's own origin, so that hours of depth lose no digits.
  if (x > 10 * kWindowS) rebase();
}

void DepthTrend::drop_before(double t) {
  while (!recent_.empty() && recent_.front().first + t0_ < t - kRecentS) {
    const auto [x, y] = recent_.front();
    recent_sums_.add(x, y, -1);
    older_sums_.add(x, y, 1);
    older_.push_back(recent_.front());
    recent_.pop_front();
  }
  while (!older_.empty() && older_.front().first + t0_ < t - kWindowS) {
    older_sums_.add(older_.front().first, older_.front().second, -1);
    older_.pop_front();
  }
}

void DepthTrend::rebase() {
  const auto origin = older_.empty() ? recent_.front() : older_.front();
  t0_ += origin.first;
  d0_ += origin.second;
  for (auto* queue : {&older_, &recent_}) {
    Sums& sums = queue == &older_ ? older_sums_ : recent_sums_;
    sums = Sums{};
    for (std::size_t i = 0; i < queue->size(); ++i) {
      auto& [x, y] = (*queue)[i];
      x -= origin.first;
      y -= origin.second;
      sums.add(x, y, 1);
    }
  }
}

bool DepthTrend::fit(const Sums& s, double noise_sd, Line& line) {
  if (s.n < static_cast<double>(kMinReports)) return false;
  const double sxx = s.xx - s.x * s.x / s.n, sxy = s.xy - s.x * s.y / s.n, syy = s.yy - s.y * s.y / s.n;
  if (!(sxx > 0)) return false;
  line.slope = sxy / sxx;
  const double scatter = std::max(0.0, syy - line.slope * sxy) / (s.n - 2);
  line.sd = std::sqrt(std::max(noise_sd * noise_sd, scatter) / sxx);
  return true;
}

bool DepthTrend::moved_since(double t_from, double noise_sd) const {
  Sums sums;
  for (const auto* queue : {&older_, &recent_}) {
    for (const auto& [x, y] : *queue) {
      if (x + t0_ >= t_from) sums.add(x, y, 1);
    }
  }
  Line line;
  return fit(sums, noise_sd, line) && std::abs(line.slope) > kSlopeSigmas * line.sd;
}

bool DepthTrend::moving(double t, double noise_sd) {
  if (judged_t_ > last_t_ && t - judged_t_ < 1.0) return judged_moving_;
  judged_t_ = t;
  judged_moving_ = judge(t, noise_sd);
  return judged_moving_;
}

bool DepthTrend::judge(double t, double noise_sd) {
  drop_before(t);
  Line whole, before, recent;
  if (!fit(older_sums_ + recent_sums_, noise_sd, whole)) return false;
  if (std::abs(whole.slope) <= kSlopeSigmas * whole.sd) return false;
  // The tool has stopped where the recent line is flat and its slope differs from the one before.
  const bool stopped = fit(older_sums_, noise_sd, before) && fit(recent_sums_, noise_sd, recent) &&
                       std::abs(recent.slope) <= kSlopeSigmas * recent.sd &&
                       std::abs(before.slope - recent.slope) > kSlopeSigmas * std::hypot(before.sd, recent.sd);
  return !stopped;
}

}  // namespace plumb::strapdown
