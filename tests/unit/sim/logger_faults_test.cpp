// A logger's dropouts and repeats against what each setting means: every gap as long as asked,
// the samples it lost exactly those between its two stamps, the repeats copies of their original
// (same stamp, or re-stamped half a period later), the rates as asked over a long stream, and no
// fault at all by default.
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/sim/logger_faults.hpp"

namespace plumb::sim {
namespace {

constexpr double kLoggerRate = 100;

std::vector<Sample> logger_clean_stream(double seconds) {
  std::vector<Sample> s(static_cast<std::size_t>(seconds * kLoggerRate));
  for (std::size_t k = 0; k < s.size(); ++k) {
    s[k].seq = k;
    s[k].t = static_cast<double>(k) / kLoggerRate;
    s[k].f = Eigen::Vector3d(0.001 * static_cast<double>(k), 1, 2);
  }
  return s;
}

TEST(LoggerFaults, OffByDefaultTheStreamIsUnchanged) {
  const auto clean = logger_clean_stream(60);
  const auto out = through_logger(clean, LoggerFaults{}, kLoggerRate, 7);
  ASSERT_EQ(out.size(), clean.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    EXPECT_EQ(out[k].seq, clean[k].seq);
    EXPECT_EQ(out[k].t, clean[k].t);
  }
}

TEST(LoggerFaults, GapsHaveTheirLengthAndLoseExactlyTheSamplesBetween) {
  const double seconds = 3600;
  const auto clean = logger_clean_stream(seconds);
  LoggerFaults faults;
  faults.dropouts_per_minute = 2;
  faults.dropout_min_s = 0.1;
  faults.dropout_max_s = 3;
  LoggerFaultLog log;
  const auto out = through_logger(clean, faults, kLoggerRate, 11, &log);
  // Poisson: 120 expected over the hour (less the time spent inside gaps, 1.55 s each on average).
  const double expected = 2 * (seconds - 1.55 * 120) / 60;
  EXPECT_NEAR(static_cast<double>(log.gaps.size()), expected, 5 * std::sqrt(expected));
  std::size_t lost = 0;
  for (const auto& g : log.gaps) {
    const double missing_s = g.first_after - g.last_before - 1 / kLoggerRate;
    EXPECT_GE(missing_s, faults.dropout_min_s - 1 / kLoggerRate - 1e-9);
    EXPECT_LE(missing_s, faults.dropout_max_s + 1 / kLoggerRate + 1e-9);
    EXPECT_EQ(g.lost, static_cast<std::size_t>(std::llround(missing_s * kLoggerRate)));
    lost += g.lost;
  }
  EXPECT_EQ(out.size() + lost, clean.size());
  // In the output stream, each gap is a step of its length and every other step is one period.
  std::size_t steps_over = 0;
  for (std::size_t k = 1; k < out.size(); ++k) {
    const double dt = out[k].t - out[k - 1].t;
    if (dt > 1.5 / kLoggerRate) {
      ++steps_over;
    } else {
      EXPECT_NEAR(dt, 1 / kLoggerRate, 1e-9);
    }
  }
  EXPECT_EQ(steps_over, log.gaps.size());
}

TEST(LoggerFaults, RepeatsAreCopiesSameStampOrRestamped) {
  for (bool restamped : {false, true}) {
    const auto clean = logger_clean_stream(600);
    LoggerFaults faults;
    faults.repeats_per_minute = 6;
    faults.repeats_restamped = restamped;
    LoggerFaultLog log;
    const auto out = through_logger(clean, faults, kLoggerRate, 3, &log);
    EXPECT_EQ(out.size(), clean.size() + log.repeats);
    EXPECT_NEAR(static_cast<double>(log.repeats), 60.0, 5 * std::sqrt(60.0));
    std::size_t copies = 0;
    for (std::size_t k = 1; k < out.size(); ++k) {
      if (out[k].seq != out[k - 1].seq) continue;
      ++copies;
      EXPECT_EQ(out[k].f, out[k - 1].f);
      EXPECT_NEAR(out[k].t - out[k - 1].t, restamped ? 0.5 / kLoggerRate : 0.0, 1e-12);
    }
    EXPECT_EQ(copies, log.repeats);
  }
}

TEST(LoggerFaults, RefusesBadSettings) {
  LoggerFaults bad;
  bad.dropouts_per_minute = 1;
  bad.dropout_min_s = 2;
  bad.dropout_max_s = 1;
  EXPECT_THROW(through_logger(logger_clean_stream(1), bad, kLoggerRate, 1), std::invalid_argument);
}

}  // namespace
}  // namespace plumb::sim
