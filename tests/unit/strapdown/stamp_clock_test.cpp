// The instants a logger's jittering stamps are integrated at (StampClock), fed by the input checks'
// nominal interval and spread as the navigator feeds them: against the true instants of the plumb
// simulator's logger clock, a tenth of a stamp's jitter where the spread is over 2 % of the
// interval (stamps that fall out of order placed by their seq), the stamps themselves otherwise (a
// regular stream; out of order in a stream without a seq), and a gap is the stamps' own step.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/sim/logger_clock.hpp"
#include "plumb/strapdown/input_checks.hpp"
#include "plumb/strapdown/stamp_clock.hpp"

namespace plumb::strapdown {
namespace {

struct ClockTrace {
  std::vector<double> instants, stamps, truth;
  double last_instant_sd = 0;
};

// A still tool's readings at `rate` for `seconds`, through a logger clock, the samples between
// `gap_from` and `gap_to` (true seconds) lost; each navigable reading's instant beside its stamp.
// seq_counts: the samples carry their seq (a file's rows are counted), or all the same one.
ClockTrace trace_stamp_clock(double rate, double seconds, double jitter_s, double ppm, double gap_from = -1,
                             double gap_to = -1, bool seq_counts = true) {
  std::vector<Sample> clean;
  for (std::size_t k = 0; k < static_cast<std::size_t>(seconds * rate); ++k) {
    Sample s;
    s.seq = seq_counts ? k : 0;
    s.t = static_cast<double>(k) / rate;
    s.f = Eigen::Vector3d(0, 0, -9.81);
    s.b = Eigen::Vector3d(20, 0, 40);
    s.flags = flags::kHasGyro;
    if (!(s.t > gap_from && s.t < gap_to)) clean.push_back(s);
  }
  sim::LoggerClock clock;
  clock.stamp_jitter_s = jitter_s;
  clock.clock_drift_ppm = ppm;
  const std::vector<Sample> stamped = sim::through_logger_clock(clean, clock, 21);
  NavigatorConfig config;
  config.accel_range = 1e9;
  config.gyro_range = 1e9;
  Counters counters;
  InputChecks checks;
  checks.reset(config, counters);
  StampClock stamp_clock;
  ClockTrace trace;
  double last_t = 0;
  for (std::size_t k = 0; k < stamped.size(); ++k) {
    InputReading in;
    if (!checks.accept(stamped[k], in, counters).navigable) continue;
    if (trace.stamps.empty()) {
      stamp_clock.restart(in.t);
    } else {
      const double dt = in.t - last_t;
      stamp_clock.next(in.t, dt, checks.dt_nominal(), checks.dt_jitter(), checks.lost_samples(dt), checks.ordered_by_seq());
    }
    last_t = in.t;
    trace.instants.push_back(stamp_clock.instant());
    trace.stamps.push_back(in.t);
    trace.truth.push_back(clean[k].t * (1 + 1e-6 * ppm));  // the drifted clock's own time, t0 = 0
  }
  trace.last_instant_sd = stamp_clock.instant_sd(checks.dt_nominal(), checks.dt_jitter(), checks.ordered_by_seq());
  return trace;
}

// The rms about the mean of (x - truth) from reading `from` on: a constant offset is no error to
// the steps.
double clock_error_rms(const std::vector<double>& x, const std::vector<double>& truth, std::size_t from) {
  double mean = 0, n = 0;
  for (std::size_t k = from; k < x.size(); ++k, n += 1) mean += x[k] - truth[k];
  mean /= n;
  double ss = 0;
  for (std::size_t k = from; k < x.size(); ++k) ss += (x[k] - truth[k] - mean) * (x[k] - truth[k] - mean);
  return std::sqrt(ss / n);
}

TEST(StampClock, JitteringStampsGiveInstantsATenthAsFarOff) {
  for (const double ppm : {50.0, -50.0}) {
    const ClockTrace trace = trace_stamp_clock(100, 600, 1e-3, ppm);
    const double stamps_rms = clock_error_rms(trace.stamps, trace.truth, 2000);
    const double instants_rms = clock_error_rms(trace.instants, trace.truth, 2000);
    std::printf("stamp clock, 1 ms jitter, %+.0f ppm: stamps %.3f ms rms off, instants %.3f ms (told %.3f ms)\n", ppm,
                stamps_rms * 1e3, instants_rms * 1e3, trace.last_instant_sd * 1e3);
    // sqrt(0.02 / 1.98) = 0.10 of the jitter, and a little from the nominal interval's own error.
    EXPECT_NEAR(stamps_rms, 1e-3, 0.05e-3);
    EXPECT_GT(instants_rms, 0.05e-3);
    EXPECT_LT(instants_rms, 0.15e-3) << ppm << " ppm";
    // What the rows' toolface sigma is told: within a third of what the instants show.
    EXPECT_NEAR(trace.last_instant_sd, instants_rms, instants_rms / 3) << ppm << " ppm";
  }
}

TEST(StampClock, RegularStampsAreTheInstants) {
  const ClockTrace trace = trace_stamp_clock(100, 120, 0, 50);
  for (std::size_t k = 0; k < trace.stamps.size(); ++k) ASSERT_EQ(trace.instants[k], trace.stamps[k]);
  EXPECT_LT(trace.last_instant_sd, 1e-9);
}

// 1 ms at 400 Hz: 4 % of the stamps fall behind the one before. Placed by their seq, every reading
// is navigated and the instants are drawn from the nominal interval, a fraction of the jitter off
// the true ones (told within a third); without a seq that counts, those readings are refused and
// the stamps are kept, the rows' toolface sigma told the stamps' jitter.
TEST(StampClock, StampsOutOfOrderArePlacedByTheirSeq) {
  const ClockTrace trace = trace_stamp_clock(400, 120, 1e-3, 50);
  EXPECT_EQ(trace.stamps.size(), trace.truth.size());
  std::size_t behind = 0;
  for (std::size_t k = 1; k < trace.stamps.size(); ++k) {
    behind += trace.stamps[k] < trace.stamps[k - 1];
    ASSERT_GT(trace.instants[k], trace.instants[k - 1]) << k;
  }
  EXPECT_GT(behind, trace.stamps.size() / 50) << "stamps behind the one before: fewer than the jitter makes";
  EXPECT_GE(trace.stamps.size(), std::size_t{47990}) << "every reading navigated but a few before the jitter is known";
  const double stamps_rms = clock_error_rms(trace.stamps, trace.truth, 4000);
  const double instants_rms = clock_error_rms(trace.instants, trace.truth, 4000);
  std::printf("stamp clock, 1 ms jitter at 400 Hz, placed by seq: %zu stamps behind, stamps %.3f ms rms off, "
              "instants %.3f ms (told %.3f ms)\n",
              behind, stamps_rms * 1e3, instants_rms * 1e3, trace.last_instant_sd * 1e3);
  EXPECT_LT(instants_rms, 0.3 * stamps_rms);
  EXPECT_NEAR(trace.last_instant_sd, instants_rms, instants_rms / 3);

  const ClockTrace unplaced = trace_stamp_clock(400, 120, 1e-3, 0, -1, -1, false);
  EXPECT_LT(unplaced.stamps.size(), std::size_t{47000}) << "stamps behind refused";
  for (std::size_t k = 4000; k < unplaced.stamps.size(); ++k) ASSERT_EQ(unplaced.instants[k], unplaced.stamps[k]);
  EXPECT_GT(unplaced.last_instant_sd, 0.6e-3);
  EXPECT_LT(unplaced.last_instant_sd, 1.2e-3);
}

// Half a second lost: the step across it is the stamps', and the instants are back within the
// jitter's tenth a few hundred readings on.
TEST(StampClock, AGapIsTheStampsOwnStep) {
  const ClockTrace trace = trace_stamp_clock(100, 300, 1e-3, 0, 150.0, 150.5);
  std::size_t after = 0;
  while (trace.truth[after] < 150.5) ++after;
  EXPECT_EQ(trace.instants[after], trace.stamps[after]);
  EXPECT_NE(trace.instants[after - 1], trace.stamps[after - 1]);
  EXPECT_LT(clock_error_rms(trace.instants, trace.truth, after + 300), 0.15e-3);
}

}  // namespace
}  // namespace plumb::strapdown
