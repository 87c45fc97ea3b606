// Depth as a rig reports it, against what each setting means: reports only once per interval and
// held (or left empty) between, every report a whole number of rounding steps, a late report
// equal to the depth that many seconds earlier, and the noise it was given.
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/sim/rig_depth.hpp"

namespace plumb::sim {
namespace {

constexpr double kRate = 100;
constexpr double kRop = 0.0437;  // m/s (157 m/h): most whole-second depths fall between 1 cm steps

RigDepthReports reports(double interval_s, double sd_m, double quantum_m, double late_s) {
  RigDepthReports r;
  r.interval_s = interval_s, r.sd_m = sd_m, r.quantum_m = quantum_m, r.late_s = late_s;
  return r;
}

// 60 s: drilling at kRop for 40 s from 1000 m, then standing still; each row with its exact depth.
std::vector<Sample> drilled(double seconds = 60) {
  std::vector<Sample> s(static_cast<std::size_t>(seconds * kRate));
  for (std::size_t k = 0; k < s.size(); ++k) {
    s[k].t = static_cast<double>(k) / kRate;
    s[k].depth_m = 1000 + kRop * std::min(s[k].t, 40.0);
    s[k].flags = flags::kHasDepth;
  }
  return s;
}

TEST(RigDepth, ReportsOncePerIntervalAndHoldsInBetween) {
  const auto exact = drilled();
  auto s = exact;
  as_rig_reports(s, reports(1, 0, 0, 0), kRate, 1);
  int changes = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    ASSERT_TRUE(s[k].flags & flags::kHasDepth) << k;
    const std::size_t reported_at = k - k % 100;  // the last whole second
    EXPECT_DOUBLE_EQ(s[k].depth_m, exact[reported_at].depth_m) << k;
    if (k > 0 && s[k].depth_m != s[k - 1].depth_m) ++changes;
  }
  EXPECT_EQ(changes, 40);  // one new value per second while drilling, none while still
  // Held, the depth trails the truth by up to one interval of drilling.
  EXPECT_NEAR(exact[199].depth_m - s[199].depth_m, 0.99 * kRop, 1e-9);
}

TEST(RigDepth, EveryReportIsAWholeNumberOfStepsWithinHalfAStep) {
  for (double quantum : {0.01, 0.03048}) {  // 1 cm, 0.1 ft
    const auto exact = drilled();
    auto s = exact;
    as_rig_reports(s, reports(1, 0, quantum, 0), kRate, 1);
    int off_the_truth = 0;
    for (std::size_t k = 0; k < s.size(); k += 100) {
      const double steps = s[k].depth_m / quantum;
      EXPECT_NEAR(steps, std::round(steps), 1e-6) << quantum << " at row " << k;
      EXPECT_LE(std::abs(s[k].depth_m - exact[k].depth_m), quantum / 2 + 1e-9) << quantum << " at row " << k;
      if (std::abs(s[k].depth_m - exact[k].depth_m) > 1e-6) ++off_the_truth;
    }
    EXPECT_GT(off_the_truth, 10) << quantum;  // the rounding does show
  }
}

TEST(RigDepth, ALateReportTellsTheDepthThatMuchEarlier) {
  const auto exact = drilled();
  auto s = exact;
  as_rig_reports(s, reports(1, 0, 0, 0.7), kRate, 1);
  for (std::size_t k = 100; k < 3000; k += 100)  // drilling at kRop, a whole second after the start
    EXPECT_NEAR(exact[k].depth_m - s[k].depth_m, 0.7 * kRop, 1e-9) << k;
  for (std::size_t k = 4200; k < s.size(); k += 100)  // standing still long enough: the truth
    EXPECT_DOUBLE_EQ(s[k].depth_m, exact[k].depth_m) << k;
  EXPECT_DOUBLE_EQ(s[0].depth_m, exact[0].depth_m);  // nothing earlier known: the first depth
}

TEST(RigDepth, EmptyBetweenReportsKeepsOnlyTheReportRows) {
  auto held = drilled(), sparse = drilled();
  const RigDepthReports given = reports(1, 0.02, 0.01, 0.5);
  as_rig_reports(held, given, kRate, 7);
  auto empty = given;
  empty.empty_between = true;
  as_rig_reports(sparse, empty, kRate, 7);
  for (std::size_t k = 0; k < sparse.size(); ++k) {
    const bool report_row = k % 100 == 0;
    EXPECT_EQ((sparse[k].flags & flags::kHasDepth) != 0, report_row) << k;
    if (report_row) EXPECT_DOUBLE_EQ(sparse[k].depth_m, held[k].depth_m) << k;
    else EXPECT_TRUE(std::isnan(sparse[k].depth_m)) << k;
  }
}

TEST(RigDepth, ReportsCarryTheNoiseTheyWereGiven) {
  const auto exact = drilled(3000);  // 3000 reports
  auto s = exact;
  as_rig_reports(s, reports(1, 0.03, 0, 0), kRate, 11);
  double sum = 0, sum2 = 0;
  int n = 0;
  for (std::size_t k = 0; k < s.size(); k += 100, ++n) {
    const double e = s[k].depth_m - exact[k].depth_m;
    sum += e, sum2 += e * e;
  }
  EXPECT_NEAR(sum / n, 0, 4 * 0.03 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.03, 0.03 * 0.06);  // the sd of 3000 draws is within ~1.3 % (1 sigma)
  // A seed gives one run; another seed another.
  auto again = exact, other = exact;
  as_rig_reports(again, reports(1, 0.03, 0, 0), kRate, 11);
  as_rig_reports(other, reports(1, 0.03, 0, 0), kRate, 12);
  EXPECT_EQ(again[500].depth_m, s[500].depth_m);
  EXPECT_NE(other[500].depth_m, s[500].depth_m);
}

TEST(RigDepth, RefusesWhatItCannotReport) {
  EXPECT_THROW(RigDepthReporter(reports(0.001, 0, 0, 0), kRate, 1), std::invalid_argument);  // shorter than a row
  EXPECT_THROW(RigDepthReporter(reports(1, -0.01, 0, 0), kRate, 1), std::invalid_argument);
  EXPECT_THROW(RigDepthReporter(reports(1, 0, 0, NAN), kRate, 1), std::invalid_argument);
  EXPECT_THROW(RigDepthReporter({}, 0, 1), std::invalid_argument);
  RigDepthReporter reporter({}, kRate, 1);
  Sample no_depth;
  EXPECT_THROW(reporter.apply(no_depth), std::invalid_argument);
}

}  // namespace
}  // namespace plumb::sim
