// Depth as a rig reports it: late, noisy, rounded, once per interval, held or left empty between.
#include "plumb/sim/rig_depth.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "scenario_checks.hpp"

namespace plumb::sim {
namespace {

constexpr Refusal require_reports{"rig depth reports"};

}  // namespace

RigDepthReporter::RigDepthReporter(const RigDepthReports& reports, double rate_hz, std::uint64_t seed)
    : reports_(reports), rng_(seed), noise_(0.0, reports.sd_m > 0 ? reports.sd_m : 1.0) {
  require_reports(std::isfinite(rate_hz) && rate_hz > 0, "the sampling rate must be finite and > 0 Hz");
  require_reports(std::isfinite(reports.interval_s) && std::llround(reports.interval_s * rate_hz) >= 1,
          "the interval between reports must be at least one row (1/rate)");
  require_reports(finite_nonneg(reports.sd_m), "the noise must be finite and >= 0 m");
  require_reports(finite_nonneg(reports.quantum_m), "the rounding step must be finite and >= 0 m");
  require_reports(finite_nonneg(reports.late_s), "the delay must be finite and >= 0 s");
  rows_per_report_ = static_cast<std::size_t>(std::llround(reports.interval_s * rate_hz));
  late_rows_ = static_cast<std::size_t>(std::llround(reports.late_s * rate_hz));
}

void RigDepthReporter::apply(Sample& sample) {
  require_reports((sample.flags & flags::kHasDepth) != 0 && std::isfinite(sample.depth_m),
          "row " + std::to_string(row_) + " has no exact depth to report");
  // Before late_rows_ rows have passed, the oldest known depth stands for the earlier ones.
  recent_.push_back(sample.depth_m);
  if (recent_.size() > late_rows_ + 1) recent_.pop_front();
  const bool fresh = row_ % rows_per_report_ == 0;
  if (fresh) {
    double reading = recent_.front();
    if (reports_.sd_m > 0) reading += noise_(rng_);
    const double q = reports_.quantum_m;
    report_ = q > 0 ? std::round(reading / q) * q : reading;
  }
  if (fresh || !reports_.empty_between) {
    sample.depth_m = report_;
  } else {
    sample.depth_m = std::numeric_limits<double>::quiet_NaN();
    sample.flags &= ~flags::kHasDepth;
  }
  ++row_;
}

void as_rig_reports(std::vector<Sample>& samples, const RigDepthReports& reports, double rate_hz, std::uint64_t seed) {
  RigDepthReporter reporter(reports, rate_hz, seed);
  for (Sample& s : samples) reporter.apply(s);
}

}  // namespace plumb::sim
