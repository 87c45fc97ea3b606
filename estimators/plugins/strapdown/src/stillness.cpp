#include "plumb/strapdown/stillness.hpp"

#include <algorithm>
#include <cmath>

namespace plumb::strapdown {

void StillnessDetector::reset() {
  window_.clear();
  f_sum_.setZero();
  w_sum_.setZero();
  f_square_sum_ = w_excess_square_sum_ = 0;
  excess_tol_ = -1;
  f_dev_max_.clear();
  b_dev_max_.clear();
  since_resum_ = 0;
  depths_.clear();
  depth_max_.clear();
  depth_min_.clear();
  candidate_ = confirmed_ = false;
  restart_stretch();
  fresh_until_ = -1e300;
  recent_reports_.clear();
  recent_sum_ = period_sum_ = period_n_ = 0;
  last_depth_.reset();
  trend_.clear();
  depth_moved_ = false;
}

void StillnessDetector::add_depth_report(double t, double depth) {
  const bool new_report = !last_depth_ || depth != *last_depth_;
  last_depth_ = depth;
  if (new_report) {
    recent_reports_.emplace_back(t, depth);
    recent_sum_ += depth;
    period_sum_ += depth;
    period_n_ += 1;
  }
  while (!recent_reports_.empty() && recent_reports_.front().first < t - config_.depth_window_s) {
    recent_sum_ -= recent_reports_.front().second;
    recent_reports_.pop_front();
  }
  // Outside a period, the period so far is the last depth_window_s.
  if (!candidate_ && !confirmed_) {
    period_sum_ = recent_sum_;
    period_n_ = static_cast<double>(recent_reports_.size());
  }
}

bool StillnessDetector::depth_means_steady(double factor) const {
  const double n_recent = static_cast<double>(recent_reports_.size()), n_before = period_n_ - n_recent;
  if (!(config_.depth_sd_m > 0) || n_recent < 1 || n_before < 5) return true;
  const double difference = recent_sum_ / n_recent - (period_sum_ - recent_sum_) / n_before;
  const double limit = StillnessConfig::kDepthMeanSigmas * config_.depth_sd_m * std::sqrt(1 / n_recent + 1 / n_before);
  return std::abs(difference) < factor * limit;
}

void StillnessDetector::restart_stretch() {
  stretch_held_ = false;
  stretch_w_.setZero();
  stretch_f_.setZero();
  stretch_n_ = 0;
}

// Exponential means with a memory of rate_memory_s: a plain mean until then.
void StillnessDetector::extend_stretch(const StillnessInput& in) {
  const double cap = last_dt_ > 0 ? std::max(1.0, config_.rate_memory_s / last_dt_) : 1e9;
  stretch_n_ = std::min(stretch_n_ + 1.0, cap);
  const double a = 1.0 / stretch_n_;
  stretch_w_ += a * (in.w_minus_expected - stretch_w_);
  stretch_f_ += a * (in.f - stretch_f_);
}

void StillnessDetector::add_to_sums(const Entry& e) {
  f_sum_ += e.f;
  w_sum_ += e.w;
  f_square_sum_ += e.f.squaredNorm();
  if (excess_tol_ >= 0) w_excess_square_sum_ += rate_excess(e.w_norm, excess_tol_);
  const double f_dev = std::abs(e.f_dev), b_dev = std::abs(e.b_dev);
  while (!f_dev_max_.empty() && f_dev_max_.back().second <= f_dev) f_dev_max_.pop_back();
  f_dev_max_.emplace_back(e.sequence, f_dev);
  while (!b_dev_max_.empty() && b_dev_max_.back().second <= b_dev) b_dev_max_.pop_back();
  b_dev_max_.emplace_back(e.sequence, b_dev);
}

void StillnessDetector::remove_from_sums(const Entry& e) {
  f_sum_ -= e.f;
  w_sum_ -= e.w;
  f_square_sum_ -= e.f.squaredNorm();
  if (excess_tol_ >= 0) w_excess_square_sum_ -= rate_excess(e.w_norm, excess_tol_);
  while (!f_dev_max_.empty() && f_dev_max_.front().first <= e.sequence) f_dev_max_.pop_front();
  while (!b_dev_max_.empty() && b_dev_max_.front().first <= e.sequence) b_dev_max_.pop_front();
}

void StillnessDetector::resum(double extra_gyro_tol) {
  f_sum_.setZero();
  w_sum_.setZero();
  f_square_sum_ = w_excess_square_sum_ = 0;
  excess_tol_ = extra_gyro_tol;
  for (const Entry& e : window_) {
    f_sum_ += e.f;
    w_sum_ += e.w;
    f_square_sum_ += e.f.squaredNorm();
    w_excess_square_sum_ += rate_excess(e.w_norm, excess_tol_);
  }
  since_resum_ = 0;
}

void StillnessDetector::measure_window(double g, double extra_gyro_tol) {
  // The rate energy counts only what exceeds the caller's ignorance of w_expected (before
  // alignment the whole earth rate): a navigation-grade gyro's noise is far below the earth rate.
  if (extra_gyro_tol != excess_tol_ || since_resum_ >= kResumEvery) resum(extra_gyro_tol);
  const double n = static_cast<double>(window_.size());
  window_f_mean_ = f_sum_ / n;
  window_w_mean_norm_ = (w_sum_ / n).norm();
  // (The window's size changes only when the readings' spacing does.)
  if (window_.size() != root_n_of_) {
    root_n_of_ = window_.size();
    root_n_ = std::sqrt(n);
  }
  window_gyro_allowance_ = config_.gyro_tol + extra_gyro_tol + 4.0 * config_.sigma_w / root_n_;
  window_b_dev_ = b_dev_max_.front().second;
  if (config_.mode == StillnessConfig::Mode::Glrt) {
    // sum |f - g u|^2 over the window, u the direction of the mean force, expanded so that the
    // running sums suffice: sum |f|^2 - 2 g u.sum f + n g^2 (u.sum f = n |mean f|).
    const double fn = window_f_mean_.norm();
    const double force_energy = std::max(0.0, f_square_sum_ - 2.0 * g * n * fn + n * g * g);
    const double ia = 1.0 / (config_.sigma_a * config_.sigma_a), iw = 1.0 / (config_.sigma_w * config_.sigma_w);
    last_statistic_ = (force_energy * ia + std::max(0.0, w_excess_square_sum_) * iw) / n;
  } else {
    last_statistic_ = f_dev_max_.front().second;
  }
}

bool StillnessDetector::window_quiet(double factor) const {
  const bool gyro_ok = window_w_mean_norm_ < factor * window_gyro_allowance_;
  if (config_.mode == StillnessConfig::Mode::Glrt) return gyro_ok && last_statistic_ < factor * config_.glrt_threshold;
  // The tolerance never falls below the sensor noise: 4 sigma per sample.
  const double accel_tol = std::max(config_.accel_tol, 4.0 * config_.sigma_a) + extra_accel_tol_;
  return gyro_ok && last_statistic_ < factor * accel_tol && window_b_dev_ < factor * config_.field_tol_uT;
}

StillnessCheck StillnessDetector::binding_check(double extra_gyro_tol) const {
  using Test = StillnessCheck::Test;
  StillnessCheck worst;
  if (window_.size() < StillnessConfig::kMinWindowSamples) return worst;
  const auto consider = [&](Test test, double statistic, double limit) {
    const StillnessCheck c{test, statistic, limit};
    if (worst.test == Test::None || c.ratio() > worst.ratio()) worst = c;
  };
  consider(Test::GyroWindow, window_w_mean_norm_, window_gyro_allowance_);
  if (config_.mode == StillnessConfig::Mode::Glrt) {
    consider(Test::Glrt, last_statistic_, config_.glrt_threshold);
  } else {
    consider(Test::Acceleration, last_statistic_, std::max(config_.accel_tol, 4.0 * config_.sigma_a) + extra_accel_tol_);
    if (window_b_dev_ > 0) consider(Test::Field, window_b_dev_, config_.field_tol_uT);
  }
  if (stretch_n_ >= 1) {
    const double n_window = static_cast<double>(window_.size());
    consider(Test::GyroStretch, stretch_w_.norm(),
             config_.gyro_tol + extra_gyro_tol + 4.0 * config_.sigma_w / std::sqrt(stretch_n_));
    consider(Test::ForceSteadiness, (window_f_mean_ - stretch_f_).norm(),
             config_.accel_drift_tol + 4.0 * config_.sigma_a * std::sqrt(1.0 / n_window + 1.0 / stretch_n_));
  }
  if (last_depth_range_) consider(Test::Depth, *last_depth_range_, config_.depth_tol_m);
  return worst;
}

const char* test_name(StillnessCheck::Test test) {
  switch (test) {
    case StillnessCheck::Test::Acceleration: return "| |f| - g |";
    case StillnessCheck::Test::Field: return "| |B| - B0 |";
    case StillnessCheck::Test::Glrt: return "GLRT statistic";
    case StillnessCheck::Test::GyroWindow: return "gyro rate";
    case StillnessCheck::Test::GyroStretch: return "gyro mean rate";
    case StillnessCheck::Test::ForceSteadiness: return "specific-force drift";
    case StillnessCheck::Test::Depth: return "depth change over 1 s";
    case StillnessCheck::Test::None: break;
  }
  return "none";
}

void StillnessTally::add(const StillnessCheck& check) {
  if (check.test == StillnessCheck::Test::None || !(check.ratio() > 1.0)) return;
  const auto k = static_cast<int>(check.test);
  ++count_[k];
  if (count_[k] == 1 || check.ratio() < closest_[k].ratio()) closest_[k] = check;
}

StillnessCheck StillnessTally::most_frequent() const {
  int best = 0;
  for (int k = 1; k < kTests; ++k)
    if (count_[k] > count_[best]) best = k;
  return count_[best] > 0 ? closest_[best] : StillnessCheck();
}

bool StillnessDetector::period_quiet(double factor, double extra_gyro_tol) const {
  if (stretch_n_ < 1) return true;
  const double allowance = config_.gyro_tol + extra_gyro_tol + 4.0 * config_.sigma_w / std::sqrt(stretch_n_);
  const double n_window = static_cast<double>(window_.size());
  const double f_allowance =
      config_.accel_drift_tol + 4.0 * config_.sigma_a * std::sqrt(1.0 / n_window + 1.0 / stretch_n_);
  const bool f_steady = (window_f_mean_ - stretch_f_).norm() < factor * f_allowance;
  return f_steady && stretch_w_.norm() < factor * allowance;
}

StillnessState StillnessDetector::update(const StillnessInput& in) {
  StillnessState out;
  if (!window_.empty() && in.t > last_t_) last_dt_ = in.t - last_t_;
  last_t_ = in.t;
  window_.push_back({in.t, in.f, in.w_minus_expected, in.f.norm() - in.g, in.field_deviation_uT.value_or(0.0),
                     in.w_minus_expected.norm(), entry_count_++});
  add_to_sums(window_.back());
  ++since_resum_;
  while (window_.size() > StillnessConfig::kMinWindowSamples && window_.front().t < in.t - config_.window_s) {
    remove_from_sums(window_.front());
    window_.pop_front();
  }
  bool depth_ok = true, depth_ok_exit = true;
  last_depth_range_.reset();
  if (in.depth_m) {
    const double d = *in.depth_m;
    depths_.emplace_back(in.t, d);
    while (!depth_max_.empty() && depth_max_.back().second <= d) depth_max_.pop_back();
    while (!depth_min_.empty() && depth_min_.back().second >= d) depth_min_.pop_back();
    depth_max_.emplace_back(depth_count_, d);
    depth_min_.emplace_back(depth_count_, d);
    ++depth_count_;
    while (depths_.size() > 2 && depths_.front().first < in.t - config_.depth_window_s) depths_.pop_front();
    const std::uint64_t oldest = depth_count_ - depths_.size();
    while (depth_max_.front().first < oldest) depth_max_.pop_front();
    while (depth_min_.front().first < oldest) depth_min_.pop_front();
    const double range = depth_max_.front().second - depth_min_.front().second;
    last_depth_range_ = range;
    add_depth_report(in.t, d);
    depth_ok = range < config_.depth_tol_m && depth_means_steady(1.0);
    depth_ok_exit = range < config_.hysteresis * config_.depth_tol_m && depth_means_steady(config_.hysteresis);
    trend_.add(in.t, d);
  }
  if (depth_moved_) {
    depth_moved_ = trend_.moving(in.t, config_.depth_sd_m);
    depth_ok = depth_ok && !depth_moved_;
  }
  const bool enough = window_.size() >= StillnessConfig::kMinWindowSamples;
  extra_accel_tol_ = in.extra_accel_tol;
  if (enough) measure_window(in.g, in.extra_gyro_tol);
  const double factor = confirmed_ ? config_.hysteresis : 1.0;
  const bool quiet = enough && (confirmed_ ? depth_ok_exit : depth_ok) && window_quiet(factor);
  // Only clear motion (a window failing twice the exit thresholds) restarts the long means: a
  // borderline window inside a slow steady turn must not give the turn a fresh start.
  if (!quiet) {
    if (!enough || !window_quiet(2.0 * config_.hysteresis)) {
      restart_stretch();
    } else if (!stretch_held_ && stretch_n_ > 0) {
      stretch_held_ = true;
      held_since_ = in.t;
    }
  } else {
    const double settle_s = 0.5 * config_.rate_memory_s;
    if (stretch_held_ && in.t - held_since_ >= settle_s && config_.mode == StillnessConfig::Mode::Magnitude &&
        !period_quiet(factor, in.extra_gyro_tol)) {
      restart_stretch();
      fresh_until_ = in.t + settle_s;
    }
    stretch_held_ = false;
    if (stretch_n_ == 0) {
      for (const Entry& e : window_) {
        StillnessInput past;
        past.f = e.f;
        past.w_minus_expected = e.w;
        extend_stretch(past);
      }
    } else {
      extend_stretch(in);
    }
  }
  const bool steady = quiet && period_quiet(factor, in.extra_gyro_tol);

  if (confirmed_) {
    if (steady) {
      out.still = true;
      out.period_start = period_start_;
      return out;
    }
    out.ended = true;
    depth_moved_ = !depth_ok_exit && trend_.moved_since(period_start_, config_.depth_sd_m);
    candidate_ = confirmed_ = false;
    return out;
  }
  if (!steady) {
    candidate_ = false;
    return out;
  }
  if (!candidate_) {
    // The whole window was quiet: the period began at its oldest sample.
    candidate_ = true;
    period_start_ = window_.front().t;
  }
  if (in.t - period_start_ >= config_.min_still_s - 1e-9 && in.t >= fresh_until_) {
    confirmed_ = true;
    out.still = out.started = true;
    out.period_start = period_start_;
  }
  return out;
}

}  // namespace plumb::strapdown
