// A logger's clock against what each setting means: a line fitted to the stamps against the true
// times has the asked rate (1 + ppm 1e-6) within its sampling error and the asked jitter as its
// residual rms; the readings are untouched; off by default nothing changes.
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/sim/logger_clock.hpp"

namespace plumb::sim {
namespace {

constexpr double kClockRate = 100;

std::vector<Sample> clock_clean_stream(double seconds, double start_s = 0) {
  std::vector<Sample> s(static_cast<std::size_t>(seconds * kClockRate));
  for (std::size_t k = 0; k < s.size(); ++k) {
    s[k].seq = k;
    s[k].t = start_s + static_cast<double>(k) / kClockRate;
    s[k].f = Eigen::Vector3d(0.001 * static_cast<double>(k), 1, 2);
    s[k].w = Eigen::Vector3d(0.1, -0.002 * static_cast<double>(k), 3);
    s[k].b = Eigen::Vector3d(20, 0, 40);
    s[k].depth_m = 0.01 * static_cast<double>(k);
    s[k].flags = flags::kHasGyro | (k % 7 == 0 ? flags::kHasDepth : 0u);
  }
  return s;
}

// Least squares of the stamps on the true times: slope, its standard error, the residuals' rms.
struct ClockLine {
  double slope = 0, slope_se = 0, residual_rms = 0;
};

ClockLine fit_clock_line(const std::vector<Sample>& truth, const std::vector<Sample>& stamped) {
  const auto n = static_cast<double>(truth.size());
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    mx += truth[k].t / n;
    my += stamped[k].t / n;
  }
  double sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    sxx += (truth[k].t - mx) * (truth[k].t - mx);
    sxy += (truth[k].t - mx) * (stamped[k].t - my);
  }
  ClockLine line;
  line.slope = sxy / sxx;
  double ss = 0;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const double r = stamped[k].t - my - line.slope * (truth[k].t - mx);
    ss += r * r;
  }
  line.residual_rms = std::sqrt(ss / (n - 2));
  line.slope_se = line.residual_rms / std::sqrt(sxx);
  return line;
}

TEST(LoggerClock, OffByDefaultTheStreamIsUnchanged) {
  const auto clean = clock_clean_stream(60, 12.5);
  const auto out = through_logger_clock(clean, LoggerClock{}, 7);
  ASSERT_EQ(out.size(), clean.size());
  for (std::size_t k = 0; k < out.size(); ++k) EXPECT_EQ(out[k].t, clean[k].t);
}

TEST(LoggerClock, StampsHaveTheAskedDriftAndJitterAndTheReadingsAreUnchanged) {
  const auto clean = clock_clean_stream(1000, 3.0);
  for (const double ppm : {50.0, -50.0, 20.0}) {
    for (const double jitter_s : {1e-3, 2e-4}) {
      LoggerClock clock;
      clock.stamp_jitter_s = jitter_s;
      clock.clock_drift_ppm = ppm;
      const auto out = through_logger_clock(clean, clock, 5);
      ASSERT_EQ(out.size(), clean.size());
      const ClockLine line = fit_clock_line(clean, out);
      // 1e5 stamps over 1000 s: the slope's error is about 0.01 ppm at 1 ms, the rms's 0.2 %.
      EXPECT_NEAR(line.slope, 1 + 1e-6 * ppm, 4 * line.slope_se) << ppm << " ppm, " << jitter_s << " s";
      EXPECT_LT(line.slope_se, 0.05e-6);
      EXPECT_NEAR(line.residual_rms, jitter_s, 0.02 * jitter_s) << ppm << " ppm, " << jitter_s << " s";
      // The clock starts right: the first stamp is the first instant's, within the jitter.
      EXPECT_NEAR(out.front().t, clean.front().t, 5 * jitter_s);
      for (std::size_t k = 0; k < out.size(); ++k) {
        EXPECT_EQ(out[k].seq, clean[k].seq);
        EXPECT_EQ(out[k].f, clean[k].f);
        EXPECT_EQ(out[k].w, clean[k].w);
        EXPECT_EQ(out[k].b, clean[k].b);
        EXPECT_EQ(out[k].depth_m, clean[k].depth_m);
        EXPECT_EQ(out[k].flags, clean[k].flags);
      }
    }
  }
}

// Drift alone: every stamp on the line, and the stamps run ahead by ppm x the elapsed time.
TEST(LoggerClock, DriftAloneIsALine) {
  const auto clean = clock_clean_stream(600);
  LoggerClock clock;
  clock.clock_drift_ppm = 50;
  const auto out = through_logger_clock(clean, clock, 1);
  for (std::size_t k = 0; k < out.size(); ++k) EXPECT_NEAR(out[k].t - clean[k].t, 50e-6 * clean[k].t, 1e-12);
  EXPECT_NEAR(out.back().t - clean.back().t, 0.03, 1e-4);  // 50 ppm of 600 s
}

TEST(LoggerClock, RefusesBadSettings) {
  LoggerClock negative;
  negative.stamp_jitter_s = -1e-3;
  EXPECT_THROW(through_logger_clock(clock_clean_stream(1), negative, 1), std::invalid_argument);
  LoggerClock runaway;
  runaway.clock_drift_ppm = 2e6;
  EXPECT_THROW(through_logger_clock(clock_clean_stream(1), runaway, 1), std::invalid_argument);
  LoggerClock not_finite;
  not_finite.clock_drift_ppm = std::nan("");
  EXPECT_THROW(through_logger_clock(clock_clean_stream(1), not_finite, 1), std::invalid_argument);
}

}  // namespace
}  // namespace plumb::sim
