// Still runs of the tool's own sensors: blocks of samples in which the specific force does not
// spread and the gyros (when present) read no turning. A still run needs min_still_s of still blocks
// and ends when motion lasts min_moving_s (a single knock does not end a connection).
#pragma once

#include <optional>

#include <Eigen/Core>

#include "plumb/clock_sync/still_run.hpp"

namespace plumb::clock_sync {

struct SensorStillnessOptions {
  double block_s = 0.1;              // samples judged together
  double accel_spread_mps2 = 0.05;   // largest axis range of f in a block that is still still
  double gyro_rate_radps = 0.02;     // |w| above this is turning (earth rate is 7e-5)
  double min_still_s = 5;
  double min_moving_s = 0.5;
  double max_gap_s = 2;              // samples further apart than this: what came before is unknown
};

class SensorStillness {
 public:
  explicit SensorStillness(SensorStillnessOptions options = {});
  // One sample; `has_gyro` false ignores w. A still run that this sample's block ended, else nothing.
  std::optional<StillRun> add_sample(double t_s, const Eigen::Vector3d& f, const Eigen::Vector3d& w, bool has_gyro);
  // One judged block (when the caller judges motion itself).
  std::optional<StillRun> add_motion(double t_s, bool moving);
  // Coverage for ClockFit::set_coverage: the first block, and the time before which every run has
  // been given.
  double first_t() const { return first_t_; }
  double settled_until() const { return last_t_ - options_.min_moving_s - options_.block_s; }

 private:
  std::optional<StillRun> close_block();

  SensorStillnessOptions options_;
  // The block being filled.
  bool block_open_ = false;
  double block_t0_ = 0, block_t_ = 0;
  Eigen::Vector3d fmin_, fmax_;
  double wmax_ = 0;
  // The still/moving state machine.
  bool have_ = false;
  double last_t_ = 0, first_t_ = 0;
  bool in_still_ = false, after_motion_ = false, seen_motion_ = false;
  double still_begin_ = 0, last_still_t_ = 0, last_moving_t_ = 0;
  bool moving_pending_ = false;
  double moving_since_ = 0;
};

}  // namespace plumb::clock_sync
