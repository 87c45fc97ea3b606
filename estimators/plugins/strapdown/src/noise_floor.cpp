#include "plumb/strapdown/noise_floor.hpp"

#include <algorithm>
#include <cmath>

namespace plumb::strapdown {

namespace {

// Per-axis standard deviation of one sample about the block mean, pooled over the three axes.
double pooled_sd(const Eigen::Vector3d& sum, double sum_sq, double n) {
  return std::sqrt(std::max(0.0, (sum_sq - sum.squaredNorm() / n) / (3.0 * (n - 1.0))));
}

}  // namespace

void NoiseFloor::add(double t, const Eigen::Vector3d& f, const Eigen::Vector3d& w, std::optional<double> depth) {
  if (block_.n == 0) block_.t0 = t;
  block_.n += 1;
  block_.f += f;
  block_.w += w;
  block_.ff += f.squaredNorm();
  block_.ww += w.squaredNorm();
  if (block_.n >= kBlockSamples && t - block_.t0 >= kBlockSeconds) {
    // A low quantile of sample standard deviations lies below the true one by about z / sqrt(2 dof)
    // of it (dof = 3 (n - 1), pooled over three axes): taken back here.
    const double low = 1.0 - kQuantileZ / std::sqrt(6.0 * (block_.n - 1.0));
    accel_blocks_.push_back(pooled_sd(block_.f, block_.ff, block_.n) / low);
    gyro_blocks_.push_back(pooled_sd(block_.w, block_.ww, block_.n) / low);
    block_ = Sums();
  }
  depth_.add(t, depth);
}

std::optional<double> NoiseFloor::floor_of(const std::vector<double>& blocks, std::size_t min_blocks) {
  if (blocks.size() < min_blocks) return std::nullopt;
  std::vector<double> sorted(blocks);
  const auto k = static_cast<std::ptrdiff_t>(kQuantile * static_cast<double>(sorted.size() - 1));
  std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
  return sorted[static_cast<std::size_t>(k)];
}

}  // namespace plumb::strapdown
