// A logger's dropouts and repeats over a whole run.
#include "plumb/sim/logger_faults.hpp"

#include <random>

#include "scenario_checks.hpp"

namespace plumb::sim {
namespace {

constexpr Refusal require_faults{"logger faults"};

}  // namespace

std::vector<Sample> through_logger(const std::vector<Sample>& samples, const LoggerFaults& faults, double rate_hz,
                                   std::uint64_t seed, LoggerFaultLog* log) {
  require_faults(std::isfinite(rate_hz) && rate_hz > 0, "the sampling rate must be finite and > 0 Hz");
  require_faults(finite_nonneg(faults.dropouts_per_minute), "the dropout rate must be finite and >= 0 per minute");
  require_faults(finite_nonneg(faults.repeats_per_minute), "the repeat rate must be finite and >= 0 per minute");
  require_faults(finite_nonneg(faults.dropout_min_s) && std::isfinite(faults.dropout_max_s) &&
                     faults.dropout_min_s <= faults.dropout_max_s,
                 "dropout lengths must be finite, >= 0, min <= max");
  if (!(faults.dropouts_per_minute > 0) && !(faults.repeats_per_minute > 0)) return samples;
  std::mt19937_64 rng(seed ^ 0x6c6f67676572ULL);  // its own stream: "logger"
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // Per sample, the chance that a dropout starts or a repeat is sent (Poisson events in time).
  const double p_drop = faults.dropouts_per_minute / 60.0 / rate_hz;
  const double p_repeat = faults.repeats_per_minute / 60.0 / rate_hz;
  std::vector<Sample> out;
  out.reserve(samples.size() + samples.size() / 100);
  double drop_until = -1;
  bool dropping = false;
  LoggerFaultLog::Gap gap;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const Sample& s = samples[k];
    // Never the first or the last sample: a gap is between two samples the navigator sees.
    const bool inside = k > 0 && k + 1 < samples.size();
    if (dropping && (s.t > drop_until || !inside)) {
      dropping = false;
      gap.first_after = s.t;
      if (log != nullptr) log->gaps.push_back(gap);
    }
    if (dropping) {
      ++gap.lost;
      continue;
    }
    if (inside && p_drop > 0 && uniform(rng) < p_drop) {
      dropping = true;
      drop_until = s.t + faults.dropout_min_s + (faults.dropout_max_s - faults.dropout_min_s) * uniform(rng);
      gap = LoggerFaultLog::Gap{out.empty() ? s.t : out.back().t, 0, 1};
      continue;
    }
    out.push_back(s);
    if (p_repeat > 0 && uniform(rng) < p_repeat) {
      Sample copy = s;
      if (faults.repeats_restamped) copy.t += 0.5 / rate_hz;
      out.push_back(copy);
      if (log != nullptr) ++log->repeats;
    }
  }
  return out;
}

}  // namespace plumb::sim
