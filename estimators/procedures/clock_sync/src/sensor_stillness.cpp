#include "plumb/clock_sync/sensor_stillness.hpp"

#include <algorithm>

namespace plumb::clock_sync {

SensorStillness::SensorStillness(SensorStillnessOptions options) : options_(options) {}

std::optional<StillRun> SensorStillness::add_sample(double t_s, const Eigen::Vector3d& f, const Eigen::Vector3d& w,
                                                    bool has_gyro) {
  std::optional<StillRun> run;
  if (block_open_ && (t_s - block_t0_ >= options_.block_s || t_s - block_t_ > options_.max_gap_s)) run = close_block();
  if (!block_open_) {
    block_open_ = true;
    block_t0_ = t_s;
    fmin_ = fmax_ = f;
    wmax_ = 0;
  }
  block_t_ = t_s;
  fmin_ = fmin_.cwiseMin(f);
  fmax_ = fmax_.cwiseMax(f);
  if (has_gyro) wmax_ = std::max(wmax_, w.norm());
  return run;
}

std::optional<StillRun> SensorStillness::close_block() {
  block_open_ = false;
  const bool moving = (fmax_ - fmin_).maxCoeff() > options_.accel_spread_mps2 || wmax_ > options_.gyro_rate_radps;
  return add_motion(0.5 * (block_t0_ + block_t_), moving);
}

std::optional<StillRun> SensorStillness::add_motion(double t_s, bool moving) {
  if (!have_ || t_s - last_t_ > options_.max_gap_s) {
    // A gap: neither the motion before it nor a still run across it is known.
    if (!have_) first_t_ = t_s;
    have_ = true;
    in_still_ = false;
    after_motion_ = false;
    moving_pending_ = false;
    seen_motion_ = false;
  }
  last_t_ = t_s;
  std::optional<StillRun> run;
  if (!moving) {
    if (!in_still_) {
      in_still_ = true;
      after_motion_ = seen_motion_;
      still_begin_ = seen_motion_ ? 0.5 * (last_moving_t_ + t_s) : t_s;
    }
    moving_pending_ = false;
    last_still_t_ = t_s;
    return run;
  }
  seen_motion_ = true;
  last_moving_t_ = t_s;
  if (!in_still_) return run;
  if (!moving_pending_) {
    moving_pending_ = true;
    moving_since_ = t_s;
  }
  if (t_s - moving_since_ >= options_.min_moving_s) {
    if (after_motion_ && last_still_t_ - still_begin_ >= options_.min_still_s)
      run = StillRun{still_begin_, 0.5 * (last_still_t_ + moving_since_)};
    in_still_ = false;
    moving_pending_ = false;
  }
  return run;
}

}  // namespace plumb::clock_sync
