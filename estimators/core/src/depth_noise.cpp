#include "plumb/core/depth_noise.hpp"

#include <algorithm>
#include <cmath>

namespace plumb {

namespace {

// The low quantile of a block statistic; none until min_blocks were seen.
std::optional<double> low_quantile(const std::vector<double>& blocks, std::size_t min_blocks, double quantile) {
  if (blocks.size() < min_blocks) return std::nullopt;
  std::vector<double> sorted(blocks);
  const auto k = static_cast<std::ptrdiff_t>(quantile * static_cast<double>(sorted.size() - 1));
  std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
  return sorted[static_cast<std::size_t>(k)];
}

}  // namespace

// Time and depth from the block's first report: the sums stay well conditioned over a 30 s block at
// kilometres of depth.
void DepthNoiseFloor::LineSums::add(double t_s, double depth) {
  if (n == 0) t0 = t_s, d0 = depth;
  const double x = t_s - t0, y = depth - d0;
  n += 1, t += x, d += y, tt += x * x, td += x * y, dd += y * y, last = x;
}

std::optional<double> DepthNoiseFloor::LineSums::held_residual_sd() const {
  const double sxx = tt - t * t / n, sxy = td - t * d / n, syy = dd - d * d / n;
  const double slope = sxx > 0 ? sxy / sxx : 0.0;
  const double sd = std::sqrt(std::max(0.0, syy - slope * sxy) / (n - 2.0));
  if (std::abs(slope) * last > kHeldLineChange * sd) return std::nullopt;
  return sd;
}

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
  if (line_.n > 0 && t - line_.t0 >= kLineBlockSeconds) {
    if (line_.n >= kMinLineReports) {
      if (const auto sd = line_.held_residual_sd()) line_blocks_.push_back(*sd);
    }
    line_ = LineSums();
  }
  line_.add(t, *depth);
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
  const auto second_difference = second_difference_sd();
  const auto line = line_sd();
  if (second_difference && line) return std::max(*second_difference, *line);
  return second_difference ? second_difference : line;
}

std::optional<double> DepthNoiseFloor::second_difference_sd() const { return low_quantile(blocks_, kMinBlocks, kQuantile); }

std::optional<double> DepthNoiseFloor::line_sd() const { return low_quantile(line_blocks_, kMinLineBlocks, kQuantile); }

}  // namespace plumb
