#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "plumb/windowed/fast_math.hpp"

namespace plumb::windowed {
namespace {

TEST(FastAtan2, MatchesLibmEverywhere) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), log_radius(-8, 8);
  double worst = 0;
  for (int i = 0; i < 200000; ++i) {
    const double a = angle(rng), r = std::pow(10.0, log_radius(rng));
    const double y = r * std::sin(a), x = r * std::cos(a);
    double d = std::abs(fast_atan2(y, x) - std::atan2(y, x));
    d = std::min(d, std::abs(d - 2 * M_PI));  // +-pi are the same angle
    worst = std::max(worst, d);
  }
  EXPECT_LT(worst, 1e-13);
}

TEST(FastAtan2, AxesAndOrigin) {
  EXPECT_DOUBLE_EQ(fast_atan2(0, 1), 0);
  EXPECT_NEAR(fast_atan2(1, 0), M_PI / 2, 1e-15);
  EXPECT_NEAR(fast_atan2(-1, 0), -M_PI / 2, 1e-15);
  EXPECT_NEAR(std::abs(fast_atan2(0, -1)), M_PI, 1e-15);
  EXPECT_EQ(fast_atan2(0, 0), 0);
  EXPECT_NEAR(fast_atan2(1, 1), M_PI / 4, 1e-15);
}

}  // namespace
}  // namespace plumb::windowed
