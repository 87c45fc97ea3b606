#include "plumb/strapdown/stamp_clock.hpp"

#include <cmath>

#include "plumb/strapdown/navigator_common.hpp"

namespace plumb::strapdown {

namespace {

// Below this spread (a fraction of the interval) the stamps are the instants: a regular stream is
// integrated exactly as stamped.
constexpr double kJitterWorthIt = 0.02;
// How much of its stamp's word each instant takes: a first-order loop, whose instants stray from
// the true ones by sqrt(k / (2 - k)) of a stamp's jitter (a tenth at 0.02) and follow the stamps
// over 1 / k readings.
constexpr double kPullToStamp = 0.02;
// Above this spread stamps fall behind the one before them (a stamp's jitter near a third of the
// interval: 1 ms at 400 Hz). Where the stream's seq does not place them, those readings are refused,
// the steps left are not one interval each (the nominal interval, their mean, comes out long), and
// instants drawn from it did worse than the stamps in the plumb simulator's family at 400 Hz
// (docs/navigator.md, "The logger's clock"): the stamps are then the instants. Placed by their seq,
// every reading is in and the steps are one interval each: the instants are drawn as below it.
constexpr double kJitterTooLarge = 0.35;

bool regularizes(double dt_nominal, double step_spread, bool in_seq_order) {
  return dt_nominal > 0 && step_spread > kJitterWorthIt * dt_nominal &&
         (in_seq_order || step_spread < kJitterTooLarge * dt_nominal);
}

}  // namespace

// The nominal interval is the steps' running mean (InputChecks), not their median: the jitter of
// consecutive steps telescopes in a mean (n steps' mean errs by sqrt(2) sigma / n) but not in a
// median (1.25 sqrt(2) sigma / sqrt(n)), and an instant carries every step's error after it.
double StampClock::next(double t, double step_dt, double dt_nominal, double step_spread, bool lost, bool in_seq_order) {
  // (A stamp behind the last instant came in by its seq: its own instant would step back.)
  if ((!regularizes(dt_nominal, step_spread, in_seq_order) || lost ||
       std::abs(step_dt - dt_nominal) > kJitterSigmas * step_spread) &&
      t > instant_) {
    instant_ = t;
    return instant_;
  }
  const double due = instant_ + dt_nominal;
  instant_ = due + kPullToStamp * (t - due);
  return instant_;
}

// A step's spread is sqrt(2) times a stamp's jitter (two stamps, independent).
double StampClock::instant_sd(double dt_nominal, double step_spread, bool in_seq_order) const {
  const double stamp_sd = step_spread / std::sqrt(2.0);
  if (regularizes(dt_nominal, step_spread, in_seq_order)) {
    return std::sqrt(kPullToStamp / (2.0 - kPullToStamp)) * stamp_sd;
  }
  return stamp_sd;
}

}  // namespace plumb::strapdown
