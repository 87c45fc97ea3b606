// plumb-survey's depth clock (components/plumb-survey): depth held until the clocks are aligned,
// then handed on on the sensors' clock; a given offset applied at once.
#include <gtest/gtest.h>

#include <cmath>

#include "depth_clock.hpp"

namespace plumb::survey_component {
namespace {

// Moving (turning at 60 rpm and drilling at 0.05 m/s) in [30, 90), [150, 210), [270, 330), [390, 420).
bool rig_moving(double t) {
  return (t >= 30 && t < 90) || (t >= 150 && t < 210) || (t >= 270 && t < 330) || (t >= 390 && t < 420);
}

TEST(DepthClock, AGivenOffsetIsAppliedAtOnce) {
  DepthClockOptions o;
  o.offset_s = 320;
  DepthClock clock(o);
  clock.add_depth({420.0, 12.5, 0, false});
  const auto aligned = clock.take_aligned();
  ASSERT_EQ(aligned.size(), 1u);
  EXPECT_DOUBLE_EQ(aligned[0].t_s, 100.0);
  EXPECT_NE(clock.describe().find("given"), std::string::npos) << clock.describe();
  EXPECT_EQ(clock.counters().front().second, 2u);  // depth_clock_state: given
}

TEST(DepthClock, DepthIsHeldUntilTheStopsAlignTheClocks) {
  DepthClock clock(DepthClockOptions{});
  double depth = 0, angle = 0;
  std::size_t held_before_alignment = 0;
  std::vector<survey::DepthReport> aligned;
  for (int i = 0; i < 48000; ++i) {
    const double t = i * 0.01;
    const bool moving = rig_moving(t);
    if (moving) {
      depth += 0.05 * 0.01;
      angle += 2 * M_PI * 0.01;
    }
    Sample s;
    s.t = t;
    s.f = Eigen::Vector3d(6.9 * std::cos(angle), -6.9 * std::sin(angle), -6.9);
    s.w = Eigen::Vector3d(0, 0, moving ? 2 * M_PI : 0);
    s.flags = flags::kHasGyro;
    clock.add_sensor(s);
    if (i % 10 == 0) {
      clock.add_depth({t + 320, depth, 0, false});  // the rig's clock, 320 s ahead
      auto now = clock.take_aligned();
      if (aligned.empty() && now.empty()) held_before_alignment = clock.held();
      aligned.insert(aligned.end(), now.begin(), now.end());
    }
  }
  EXPECT_GT(held_before_alignment, 1000u);  // nothing went to the detector before the alignment
  ASSERT_TRUE(clock.alignment().has_value()) << clock.describe();
  EXPECT_NEAR(clock.alignment()->offset_s, 320, 0.1) << clock.describe();
  ASSERT_FALSE(aligned.empty());
  // Every depth on the sensors' clock: the first report (sensor time 0) and the last (479.9 s).
  EXPECT_NEAR(aligned.front().t_s, 0, 0.1);
  EXPECT_NEAR(aligned.back().t_s, 479.9, 0.1);
  EXPECT_EQ(clock.counters().front().second, 1u);  // depth_clock_state: estimated
}

}  // namespace
}  // namespace plumb::survey_component
