// Measured depth as a drilling rig delivers it: a report once a second or so, read off the block
// position with some noise, rounded to the rig's display step (1 cm, or 0.1 ft), sent up to a second
// after the fact, and either held on the rows between reports or left empty there. The simulators
// write the exact depth; this turns it into what a navigator would be fed from a rig.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <random>
#include <vector>

#include "plumb/core/sample.hpp"

namespace plumb::sim {

struct RigDepthReports {
  double interval_s = 1;        // one report per interval (a whole number of rows, at least one)
  double sd_m = 0;              // white noise of each report
  double quantum_m = 0.01;      // each report rounded to this step, after the noise (0.03048: 0.1 ft); 0: not rounded
  double late_s = 0;            // a report tells the depth this long before the row it arrives on
  bool empty_between = false;   // rows without a fresh report: held (false) or no depth, NaN (true)
};

// Rewrites the depth of samples given in order, one at a time (a stream or a whole run). Every
// sample must carry its exact depth (flags::kHasDepth). Deterministic for a seed.
class RigDepthReporter {
 public:
  // Throws std::invalid_argument for a rate or report figure that is not finite, negative, or an
  // interval shorter than one row.
  RigDepthReporter(const RigDepthReports& reports, double rate_hz, std::uint64_t seed);
  // Throws std::invalid_argument for a sample without a depth.
  void apply(Sample& sample);

 private:
  RigDepthReports reports_;
  std::size_t rows_per_report_ = 1;
  std::size_t late_rows_ = 0;
  std::deque<double> recent_;   // exact depths of the last late_rows_ + 1 rows, oldest first
  std::size_t row_ = 0;
  double report_ = 0;
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_;
};

// The same over a whole run.
void as_rig_reports(std::vector<Sample>& samples, const RigDepthReports& reports, double rate_hz, std::uint64_t seed);

}  // namespace plumb::sim
