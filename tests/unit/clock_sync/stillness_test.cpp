// Still runs of the depth and of the sensors: where they begin and end, what is not a run.
#include <gtest/gtest.h>

#include <cmath>

#include "plumb/clock_sync/depth_stillness.hpp"
#include "plumb/clock_sync/sensor_stillness.hpp"

namespace plumb::clock_sync {
namespace {

// Depth: drilling at 0.05 m/s until 100 s, standing until 160 s, drilling again; reports every 0.5 s.
double depth_of(double t) { return t < 100 ? 0.05 * t : (t < 160 ? 5.0 : 5.0 + 0.05 * (t - 160)); }

TEST(DepthStillness, AStopBetweenMotionIsARun) {
  DepthStillness d;
  std::vector<StillRun> runs;
  for (double t = 0; t < 300; t += 0.5)
    if (auto r = d.add(t, depth_of(t))) runs.push_back(*r);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_NEAR(runs[0].begin_s, 100, 0.5);
  EXPECT_NEAR(runs[0].end_s, 160, 0.5);
  EXPECT_NEAR(runs[0].mid_s(), 130, 0.3);
}

TEST(DepthStillness, AStandAtTheStartOrAcrossAGapIsNotARun) {
  DepthStillness d;
  // Standing from the first report: its beginning is unknown.
  for (double t = 0; t < 60; t += 1) EXPECT_FALSE(d.add(t, 5.0).has_value());
  for (double t = 60; t < 80; t += 1) EXPECT_FALSE(d.add(t, 5.0 + 0.05 * (t - 59)).has_value());
  // Standing, then a 30 s silence, then moving: the end is unknown.
  for (double t = 80; t < 120; t += 1) EXPECT_FALSE(d.add(t, 7.0).has_value());
  for (double t = 150; t < 170; t += 1) EXPECT_FALSE(d.add(t, 7.0 + 0.05 * (t - 149)).has_value());
}

TEST(DepthStillness, APauseShorterThanTheMinimumIsNotARun) {
  DepthStillness d;
  std::size_t runs = 0;
  for (double t = 0; t < 200; t += 1) {
    const double depth = t < 50 ? 0.05 * t : (t < 53 ? 2.5 : 2.5 + 0.05 * (t - 53));
    runs += d.add(t, depth).has_value();
  }
  EXPECT_EQ(runs, 0u);
}

TEST(SensorStillness, RotationStoppingAndStartingFromTheSamples) {
  // 100 Hz, turning at 60 rpm with 5 s ramps; still from 50 s to 90 s on the truth's clock.
  SensorStillness s;
  std::vector<StillRun> runs;
  const double g = 9.80665, incl = 0.785;
  double angle = 0;
  for (int i = 0; i < 15000; ++i) {
    const double t = i * 0.01;
    double rate = 2 * M_PI;  // rad/s
    if (t >= 45 && t < 50) rate *= (50 - t) / 5;
    else if (t >= 50 && t < 90) rate = 0;
    else if (t >= 90 && t < 95) rate *= (t - 90) / 5;
    angle += rate * 0.01;
    const Eigen::Vector3d f(g * std::sin(incl) * std::cos(angle), -g * std::sin(incl) * std::sin(angle), -g * std::cos(incl));
    if (auto r = s.add_sample(t, f, Eigen::Vector3d(0, 0, rate), true)) runs.push_back(*r);
  }
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_NEAR(runs[0].begin_s, 50, 0.15);
  EXPECT_NEAR(runs[0].end_s, 90, 0.15);
}

TEST(SensorStillness, AKnockDoesNotEndAStop) {
  SensorStillness s;
  std::vector<StillRun> runs;
  for (int i = 0; i < 2000; ++i) {
    const double t = i * 0.1;
    const bool moving = t < 50 || t >= 150 || (t >= 100 && t < 100.25);
    if (auto r = s.add_motion(t, moving)) runs.push_back(*r);
  }
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_NEAR(runs[0].begin_s, 50, 0.1);
  EXPECT_NEAR(runs[0].end_s, 150, 0.1);
}

}  // namespace
}  // namespace plumb::clock_sync
