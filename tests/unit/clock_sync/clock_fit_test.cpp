// Offset and drift of the depth clock recovered from rig days built with a known clock error.
#include <gtest/gtest.h>

#include <cmath>

#include "rig_day.hpp"

namespace plumb::clock_sync {
namespace {

TEST(ClockFit, RecoversFiveMinutesTwentyAndFiftyPpm) {
  test::RigDay day;
  day.hours = 24;
  day.plan();
  auto f = day.fit();
  const auto& e = f.estimate();
  ASSERT_TRUE(e.has_value()) << f.why_not();
  const double truth = day.offset_s + day.drift * e->t_ref_s;
  EXPECT_LT(std::abs(e->offset_s - truth), 0.1) << describe(e, f.depth_runs(), f.sensor_runs());
  EXPECT_LT(std::abs(e->drift - day.drift), 10e-6) << describe(e, f.depth_runs(), f.sensor_runs());
  EXPECT_GE(e->matched, 35u);
  // A depth stamp lands on the sensor clock where the tool was: within 0.1 s inside the day, and
  // within 3 sigma (offset and drift) at its ends.
  for (double t_s : {20000.0, 40000.0, 60000.0})
    EXPECT_NEAR(e->sensor_time(day.depth_clock(t_s)), t_s, 0.1);
  for (double t_s : {100.0, 86000.0}) {
    const double sd = std::hypot(e->offset_sd_s, e->drift_sd * (t_s - e->t_ref_s));
    EXPECT_NEAR(e->sensor_time(day.depth_clock(t_s)), t_s, 3 * sd);
  }
  std::printf("%s\n", describe(e, f.depth_runs(), f.sensor_runs()).c_str());
}

TEST(ClockFit, RecoversAnOffsetOfFiftyYears) {
  // plumb-wits stamps in ns since 1970, a simulator from 0: the offset is any size.
  test::RigDay day;
  day.offset_s = 1.79e9;
  day.drift = -20e-6;
  day.hours = 4;
  day.plan();
  auto f = day.fit();
  const auto& e = f.estimate();
  ASSERT_TRUE(e.has_value()) << f.why_not();
  EXPECT_LT(std::abs(e->offset_s - (day.offset_s + day.drift * e->t_ref_s)), 0.1);
}

TEST(ClockFit, PeriodicStopsWaitForAStopThatTellsOffsetsApart) {
  // Stands and stops all alike, and each stream sees a different part of the day: shifting by a
  // whole stand explains the stops as well, so no estimate is given.
  StillRun sensor_runs[] = {{100, 300}, {1800, 2000}, {3500, 3700}};
  ClockFit f;
  for (const auto& r : sensor_runs) f.add_sensor_run(r);
  // The depth feed saw two of them, 320 s later on its clock.
  f.add_depth_run({1800 + 320, 2000 + 320});
  f.add_depth_run({3500 + 320, 3700 + 320});
  EXPECT_FALSE(f.estimate().has_value());
  EXPECT_NE(f.why_not().find("tells them apart"), std::string::npos) << f.why_not();
  // A stop of its own length settles it.
  f.add_sensor_run({5200, 5300});
  f.add_depth_run({5200 + 320, 5300 + 320});
  ASSERT_TRUE(f.estimate().has_value()) << f.why_not();
  EXPECT_NEAR(f.estimate()->offset_s, 320, 0.01);
  EXPECT_EQ(f.estimate()->matched, 3u);
}

TEST(ClockFit, AStopTheOtherStreamWatchedAndDidNotSeeRulesAnOffsetOut) {
  // Alike stops, the depth feed's last one not settled yet: shifting by a stand matches as many,
  // but puts the sensors' first stop where the depth was watching and standing nowhere.
  ClockFit f;
  for (double t : {100.0, 165.0, 230.0, 295.0, 360.0}) f.add_sensor_run({t, t + 30});
  for (double t : {100.0, 165.0, 230.0, 295.0}) f.add_depth_run({t + 320, t + 30 + 320});
  f.set_coverage(320 + 0, 320 + 380, 0, 420);
  ASSERT_TRUE(f.estimate().has_value()) << f.why_not();
  EXPECT_NEAR(f.estimate()->offset_s, 320, 0.01);
  EXPECT_EQ(f.estimate()->matched, 4u);
}

TEST(ClockFit, NothingBeforeTwoStopsAgree) {
  ClockFit f;
  EXPECT_FALSE(f.estimate().has_value());
  f.add_sensor_run({100, 300});
  f.add_depth_run({420, 620});
  EXPECT_FALSE(f.estimate().has_value());
  EXPECT_NE(f.why_not().find("1 stop(s) matched"), std::string::npos) << f.why_not();
  // A depth stop of another length is another stop.
  f.add_sensor_run({2000, 2100});
  f.add_depth_run({2320, 2700});
  EXPECT_FALSE(f.estimate().has_value());
}

}  // namespace
}  // namespace plumb::clock_sync
