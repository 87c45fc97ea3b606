#include "plumb/bridge/sample_checker.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_samples.hpp"

namespace plumb::bridge {
namespace {

TEST(SampleChecker, CleanStreamIsUntouched) {
  Counters c;
  SampleChecker checker(c);
  for (auto s : test::make_samples(0, 100)) {
    const auto before = s.flags;
    ASSERT_TRUE(checker.check(s));
    EXPECT_EQ(s.flags, before);
  }
  EXPECT_EQ(c.problems(), 0u);
}

TEST(SampleChecker, GapIsCountedWithTheNumberMissingAndFlagged) {
  Counters c;
  SampleChecker checker(c);
  Sample a = test::make_sample(10), b = test::make_sample(15);
  checker.check(a);
  ASSERT_TRUE(checker.check(b));
  EXPECT_TRUE(b.flags & flags::kGapBefore);
  EXPECT_EQ(c.seq_gaps, 1u);
  EXPECT_EQ(c.samples_missing, 4u);
}

TEST(SampleChecker, DuplicatesAndStaleRepeatsAreDropped) {
  Counters c;
  SampleChecker checker(c);
  Sample s5 = test::make_sample(5), s5again = test::make_sample(5), s3 = test::make_sample(3), s6 = test::make_sample(6);
  EXPECT_TRUE(checker.check(s5));
  EXPECT_FALSE(checker.check(s5again));
  EXPECT_FALSE(checker.check(s3));
  EXPECT_TRUE(checker.check(s6));
  EXPECT_EQ(c.duplicates, 2u);
  EXPECT_EQ(c.seq_gaps, 0u);
  EXPECT_EQ(s6.flags & flags::kGapBefore, 0u);
}

TEST(SampleChecker, BoardRestartIsCountedAndKept) {
  Counters c;
  SampleChecker checker(c);
  Sample late = test::make_sample(100000), first = test::make_sample(0);
  checker.check(late);
  EXPECT_TRUE(checker.check(first));
  EXPECT_EQ(c.seq_restarts, 1u);
  EXPECT_TRUE(first.flags & flags::kGapBefore);
  EXPECT_EQ(c.time_backwards, 1u);
}

TEST(SampleChecker, AfterTheDeviceCameBackAnOldSequenceNumberIsARestartNotADuplicate) {
  Counters c;
  SampleChecker checker(c);
  Sample a = test::make_sample(10), b = test::make_sample(3), d = test::make_sample(3);
  checker.check(a);
  checker.new_stream();
  EXPECT_TRUE(checker.check(b));   // the board restarted while away: kept
  EXPECT_FALSE(checker.check(d));  // a real duplicate within the new stream: dropped
  EXPECT_EQ(c.seq_restarts, 1u);
  EXPECT_EQ(c.duplicates, 1u);
}

TEST(SampleChecker, AfterTheDeviceCameBackLostSamplesAreAGap) {
  Counters c;
  SampleChecker checker(c);
  Sample a = test::make_sample(10), b = test::make_sample(15);
  checker.check(a);
  checker.new_stream();
  checker.check(b);
  EXPECT_EQ(c.seq_gaps, 1u);
  EXPECT_EQ(c.samples_missing, 4u);
}

TEST(SampleChecker, TimeGoingBackwardsIsFlaggedOnce) {
  Counters c;
  SampleChecker checker(c);
  Sample a = test::make_sample(0), b = test::make_sample(1), d = test::make_sample(2);
  a.t = 5.0;
  b.t = 4.0;
  d.t = 4.001;
  checker.check(a);
  checker.check(b);
  checker.check(d);
  EXPECT_TRUE(b.flags & flags::kTimeBackwards);
  EXPECT_FALSE(d.flags & flags::kTimeBackwards);
  EXPECT_EQ(c.time_backwards, 1u);
}

TEST(SampleChecker, NonFiniteInAnyChannelIsCountedOncePerSample) {
  Counters c;
  SampleChecker checker(c);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (int channel = 0; channel < 10; ++channel) {
    Sample s = test::make_sample(static_cast<std::uint64_t>(channel));
    double* slots[10] = {&s.f.x(), &s.f.y(), &s.f.z(), &s.b.x(), &s.b.y(), &s.b.z(), &s.w.x(), &s.w.y(), &s.w.z(), &s.temp_c};
    *slots[channel] = channel % 2 ? nan : -inf;
    checker.check(s);
    EXPECT_TRUE(s.flags & flags::kNotFinite) << channel;
    EXPECT_FALSE(s.flags & flags::kOutOfRange) << channel;
  }
  EXPECT_EQ(c.not_finite, 10u);
  EXPECT_EQ(c.out_of_range, 0u);
}

TEST(SampleChecker, SaturationAndOutOfRangeFollowTheConfiguredLimits) {
  Counters c;
  Limits limits;
  limits.accel_full_scale = 20;
  limits.accel_max = 50;
  limits.mag_full_scale = 100;
  limits.mag_max = 500;
  SampleChecker checker(c, limits);
  Sample at_rail = test::make_sample(0), beyond = test::make_sample(1), mag = test::make_sample(2),
         hot = test::make_sample(3), inside = test::make_sample(4);
  at_rail.f.z() = -20.0;
  beyond.f.x() = 50.5;
  mag.b.y() = 100.0;
  hot.temp_c = 300;
  inside.f.z() = 19.99;
  for (Sample* s : {&at_rail, &beyond, &mag, &hot, &inside}) checker.check(*s);
  EXPECT_TRUE(at_rail.flags & flags::kAccelSaturated);
  EXPECT_FALSE(at_rail.flags & flags::kOutOfRange);
  EXPECT_TRUE(beyond.flags & flags::kOutOfRange);
  EXPECT_TRUE(mag.flags & flags::kMagSaturated);
  EXPECT_TRUE(hot.flags & flags::kOutOfRange);
  EXPECT_EQ(inside.flags & flags::kUnusable, 0u);
  EXPECT_EQ(c.saturated, 3u);  // at_rail, beyond (also past the rail), mag
  EXPECT_EQ(c.out_of_range, 2u);
}

TEST(SampleChecker, BoardCannotClaimCalibrationOrHideProblems) {
  Counters c;
  SampleChecker checker(c);
  Sample s = test::make_sample(0);
  s.flags |= flags::kCalibrated | flags::kNotFinite;
  checker.check(s);
  EXPECT_EQ(s.flags & (flags::kCalibrated | flags::kNotFinite), 0u);
}

}  // namespace
}  // namespace plumb::bridge
