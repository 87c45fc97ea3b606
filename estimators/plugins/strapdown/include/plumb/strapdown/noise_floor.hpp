// The sensor noise as the data show it, for a user who did not state it. The readings are cut into
// short blocks; each block gives the spread of f and of w about the block's mean, and the rig's
// depth reports the spread of their second differences (blind to a steady rate of penetration). A
// low quantile over the blocks seen is
// the floor: the quietest stretches, a still tool, whatever moved in between. It is a noise per
// sample and per axis, as the detector and the filter use it.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "plumb/core/depth_noise.hpp"

namespace plumb::strapdown {

class NoiseFloor {
 public:
  // Each reading in time order; depth when the row carries one.
  void add(double t, const Eigen::Vector3d& f, const Eigen::Vector3d& w, std::optional<double> depth);
  // Once aligned only the depth's noise is still followed: a swell shows over minutes.
  void add_depth(double t, std::optional<double> depth) { depth_.add(t, depth); }
  void clear() { *this = NoiseFloor(); }
  // Per-sample standard deviation per axis; none until enough blocks were seen.
  std::optional<double> accel_sd() const { return floor_of(accel_blocks_, kMinBlocks); }
  std::optional<double> gyro_sd() const { return floor_of(gyro_blocks_, kMinBlocks); }
  std::optional<double> depth_sd() const { return depth_.sd(); }
  // Bumped each time a block ends: the caller refreshes what it derives from the floor then.
  std::size_t blocks() const { return accel_blocks_.size() + depth_.blocks(); }

  static constexpr double kBlockSeconds = 1.0;       // at least this long ...
  static constexpr double kBlockSamples = 50;        // ... and this many readings
  static constexpr std::size_t kMinBlocks = 5;
  static constexpr double kQuantile = 0.25;
  static constexpr double kQuantileZ = 0.674;  // the standard normal's 75th percentile

 private:
  static std::optional<double> floor_of(const std::vector<double>& blocks, std::size_t min_blocks);
  struct Sums {
    double n = 0, t0 = 0;
    Eigen::Vector3d f = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
    double ff = 0, ww = 0;
  };
  Sums block_;
  std::vector<double> accel_blocks_, gyro_blocks_;
  DepthNoiseFloor depth_;
};

}  // namespace plumb::strapdown
