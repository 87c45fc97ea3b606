// A logger's clock over a whole run.
#include "plumb/sim/logger_clock.hpp"

#include <cmath>
#include <random>

#include "scenario_checks.hpp"

namespace plumb::sim {
namespace {

constexpr Refusal require_clock{"logger clock"};

}  // namespace

std::vector<Sample> through_logger_clock(const std::vector<Sample>& samples, const LoggerClock& clock,
                                         std::uint64_t seed) {
  require_clock(finite_nonneg(clock.stamp_jitter_s), "the stamp jitter must be finite and >= 0 s");
  require_clock(std::isfinite(clock.clock_drift_ppm) && std::abs(clock.clock_drift_ppm) < 1e6,
                "the clock drift must be finite and within +-1e6 ppm");
  if (samples.empty() || (!(clock.stamp_jitter_s > 0) && clock.clock_drift_ppm == 0)) return samples;
  std::mt19937_64 rng(seed ^ 0x636c6f636bULL);  // its own stream: "clock"
  std::normal_distribution<double> jitter(0.0, 1.0);
  const double t0 = samples.front().t, rate = 1.0 + 1e-6 * clock.clock_drift_ppm;
  std::vector<Sample> out = samples;
  for (Sample& s : out) {
    s.t = t0 + (s.t - t0) * rate;
    if (clock.stamp_jitter_s > 0) s.t += clock.stamp_jitter_s * jitter(rng);
  }
  return out;
}

}  // namespace plumb::sim
