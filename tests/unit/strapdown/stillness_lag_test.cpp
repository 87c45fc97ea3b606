// The stillness decision with a fixed lag: readings wait lag_s, a stop that ends takes back its last
// lag_s of stillness, a stop shorter than that vanishes, and the end of data drains the queue.
#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/strapdown/stillness_lag.hpp"

namespace plumb::strapdown::test {
namespace {

constexpr double kDt = 0.125;

// Readings every 0.125 s (exact in binary). The detector's decisions: still from confirm_t (started there) to end_t (ended there).
StillnessState decision(double t, double confirm_t, double end_t) {
  StillnessState s;
  s.still = t >= confirm_t - 1e-9 && t < end_t - 1e-9;
  s.started = std::abs(t - confirm_t) < 1e-9;
  s.ended = std::abs(t - end_t) < 1e-9;
  s.period_start = confirm_t - 0.5;
  return s;
}

std::vector<StillnessLag::Entry> pass_through_lag(double lag_s, double confirm_t, double end_t, double until_t) {
  StillnessLag lag;
  lag.reset(lag_s);
  std::vector<StillnessLag::Entry> passed;
  for (int k = 0; k * kDt <= until_t; ++k) {
    InputReading in;
    in.t = k * kDt;
    lag.push(in, decision(in.t, confirm_t, end_t));
    while (const std::optional<StillnessLag::Entry> e = lag.pop_ready()) passed.push_back(*e);
  }
  while (const std::optional<StillnessLag::Entry> e = lag.pop_any()) passed.push_back(*e);
  return passed;
}

struct Seen {
  int still = 0, started = 0, ended = 0;
  double start_t = -1, end_t = -1;
};

Seen seen(const std::vector<StillnessLag::Entry>& entries) {
  Seen s;
  for (const auto& e : entries) {
    s.still += e.still.still;
    if (e.still.started) {
      ++s.started;
      s.start_t = e.reading.t;
    }
    if (e.still.ended) {
      ++s.ended;
      s.end_t = e.reading.t;
    }
  }
  return s;
}

TEST(StillnessLag, WithoutLagEveryReadingPassesAsJudged) {
  StillnessLag lag;
  lag.reset(0);
  InputReading in;
  in.t = 1;
  lag.push(in, decision(1, 1, 5));
  const std::optional<StillnessLag::Entry> e = lag.pop_ready();
  ASSERT_TRUE(e);
  EXPECT_TRUE(e->still.started);
  EXPECT_FALSE(lag.pop_ready());
  const Seen s = seen(pass_through_lag(0, 2, 8, 12));
  EXPECT_EQ(s.still, 48);
  EXPECT_NEAR(s.end_t, 8, 1e-9);
}

TEST(StillnessLag, ReadingsWaitTheLag) {
  StillnessLag lag;
  lag.reset(2);
  for (int k = 0; k < 16; ++k) {
    InputReading in;
    in.t = k * kDt;
    lag.push(in, StillnessState());
    EXPECT_FALSE(lag.pop_ready()) << k;
  }
  InputReading in;
  in.t = 2.0;
  lag.push(in, StillnessState());
  const std::optional<StillnessLag::Entry> e = lag.pop_ready();
  ASSERT_TRUE(e);
  EXPECT_EQ(e->reading.t, 0.0);
}

TEST(StillnessLag, AStopThatEndsTakesBackItsLastLagSeconds) {
  const Seen s = seen(pass_through_lag(2, 2, 8, 12));
  EXPECT_EQ(s.started, 1);
  EXPECT_NEAR(s.start_t, 2, 1e-9);
  EXPECT_EQ(s.ended, 1);
  // The readings after 6 (less than 2 s before the end at 8) were not still: the end moves back to
  // the first of them.
  EXPECT_NEAR(s.end_t, 6.125, 1e-9);
  EXPECT_EQ(s.still, 33);
}

TEST(StillnessLag, AStopShorterThanTheLagVanishes) {
  const Seen s = seen(pass_through_lag(2, 2, 3.5, 12));
  EXPECT_EQ(s.started, 0);
  EXPECT_EQ(s.ended, 0);
  EXPECT_EQ(s.still, 0);
}

TEST(StillnessLag, TheEndOfDataDrainsWithTheDecisionsKnown) {
  // Still to the last reading: nothing took it back, every waiting reading is still.
  const Seen s = seen(pass_through_lag(2, 2, 100, 12));
  EXPECT_EQ(s.started, 1);
  EXPECT_EQ(s.ended, 0);
  EXPECT_EQ(s.still, 81);
}

TEST(StillnessLag, AnEndWithoutItsFlagStaysWithout) {
  // A gap makes the detector forget its period: not still again, without an end of its own.
  StillnessLag lag;
  lag.reset(1);
  std::vector<StillnessLag::Entry> passed;
  for (int k = 0; k <= 64; ++k) {
    InputReading in;
    in.t = k * kDt;
    StillnessState s;
    s.still = k >= 16 && k < 48;
    s.started = k == 16;
    lag.push(in, s);
    while (const std::optional<StillnessLag::Entry> e = lag.pop_ready()) passed.push_back(*e);
  }
  while (const std::optional<StillnessLag::Entry> e = lag.pop_any()) passed.push_back(*e);
  const Seen s = seen(passed);
  EXPECT_EQ(s.started, 1);
  EXPECT_EQ(s.ended, 0);
  EXPECT_EQ(s.still, 25);
}

}  // namespace
}  // namespace plumb::strapdown::test
