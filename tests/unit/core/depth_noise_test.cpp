// The depth noise floor against depth reports of known noise: white noise read by both statistics,
// a swell that the second difference cannot see read by the spread about a line, drilling at a
// steady rate taken for no noise at all, and its starts and stops neither.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "plumb/core/depth_noise.hpp"

namespace plumb {
namespace {

// Reports at 1 Hz for `seconds`: a rate of penetration, a swell and white noise.
DepthNoiseFloor depth_floor_of(double seconds, double rop_mps, double swell_amplitude_m, double swell_period_s, double noise_m,
                               unsigned seed) {
  DepthNoiseFloor floor;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> white(0, noise_m);
  const double phase = std::uniform_real_distribution<double>(0, 2 * std::numbers::pi)(rng);
  for (double t = 0; t < seconds; t += 1) {
    const double swell = swell_amplitude_m * std::sin(2 * std::numbers::pi * t / swell_period_s + phase);
    floor.add(t, 1500 + rop_mps * t + swell + white(rng));
  }
  return floor;
}

TEST(DepthNoiseFloor, WhiteNoiseIsReadByBothStatistics) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const DepthNoiseFloor floor = depth_floor_of(600, 0, 0, 10, 0.03, seed);
    ASSERT_TRUE(floor.sd() && floor.line_sd());
    // A low quantile of 20 blocks of 30 reports: within a quarter of the truth, below it more often.
    EXPECT_NEAR(*floor.sd(), 0.03, 0.0075) << seed;
    EXPECT_NEAR(*floor.line_sd(), 0.03, 0.0075) << seed;
  }
}

TEST(DepthNoiseFloor, ASwellIsNoiseThatTheSecondDifferenceMisses) {
  for (const double period : {6.0, 10.0, 16.0}) {
    // 0.2 m of heave on the depth of a string held in the slips: an rms of 0.141 m.
    const DepthNoiseFloor floor = depth_floor_of(600, 0, 0.2, period, 0.01, 7);
    const double rms = std::sqrt(0.2 * 0.2 / 2 + 0.01 * 0.01);
    ASSERT_TRUE(floor.sd());
    EXPECT_GT(*floor.sd(), 0.85 * rms) << period;
    EXPECT_LT(*floor.sd(), 1.1 * rms) << period;
  }
  // Ready after a block of half a minute, not before.
  EXPECT_FALSE(depth_floor_of(29, 0, 0.2, 10, 0.01, 7).line_sd());
  EXPECT_TRUE(depth_floor_of(32, 0, 0.2, 10, 0.01, 7).line_sd());
}

// Drilling 40 s at 3 cm/s and standing 20 s, over and over: most half-minute blocks hold a start
// or a stop, which a line would call 5-10 cm of noise.
TEST(DepthNoiseFloor, StartsAndStopsAreNoNoise) {
  DepthNoiseFloor floor;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> white(0, 0.01);
  double depth = 1500;
  for (double t = 0; t < 1200; t += 1) {
    if (std::fmod(t, 60.0) >= 20) depth += 0.03;
    floor.add(t, depth + white(rng));
  }
  // Read as the white noise (the second differences' low quartile of 5 s blocks errs low), not
  // as the kinks.
  ASSERT_TRUE(floor.sd());
  EXPECT_GT(*floor.sd(), 0.005);
  EXPECT_LT(*floor.sd(), 0.013);
}

TEST(DepthNoiseFloor, ASteadyRateOfPenetrationIsNoNoise) {
  const DepthNoiseFloor floor = depth_floor_of(600, 0.05, 0, 10, 1e-4, 3);
  ASSERT_TRUE(floor.sd());
  EXPECT_LT(*floor.sd(), 2e-4);
}

}  // namespace
}  // namespace plumb
