#include "plumb/core/depth_noise.hpp"

#include <algorithm>
#include <cmath>

namespace plumb {

void DepthNoiseFloor::add(double t, std::optional<double> depth) {
  // Reports that repeat exactly (a still tool, quantized) are not counted, which errs towards more
  // noise. White noise gives the second difference a variance of 6 sigma^2.
  if (!depth) {
    last_row_had_depth_ = false;
    return;
  }
  const bool report = !last_row_had_depth_ || reports_.empty() || *depth != reports_.back();
  last_row_had_depth_ = true;
  if (!report) return;
  if (reports_.size() == 2) {
    if (terms_ == 0) t0_ = t;
    const double d2 = *depth - 2.0 * reports_[1] + reports_[0];
    sq_ += d2 * d2;
    terms_ += 1;
    if (terms_ >= 3 && t - t0_ >= kBlockSeconds) {
      blocks_.push_back(std::sqrt(sq_ / terms_ / 6.0));
      sq_ = terms_ = 0;
    }
    reports_.erase(reports_.begin());
  }
  reports_.push_back(*depth);
}

std::optional<double> DepthNoiseFloor::sd() const {
  if (blocks_.size() < kMinBlocks) return std::nullopt;
  std::vector<double> sorted(blocks_);
  const auto k = static_cast<std::ptrdiff_t>(kQuantile * static_cast<double>(sorted.size() - 1));
  std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
  return sorted[static_cast<std::size_t>(k)];
}

}  // namespace plumb
