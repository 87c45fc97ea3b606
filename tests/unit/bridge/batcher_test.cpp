#include "batcher.hpp"

#include <gtest/gtest.h>

namespace plumb::bridge_component {
namespace {

using namespace std::chrono_literals;

TEST(Batcher, FullAtThirtyTwoSamples) {
  Batcher b;
  const auto t = Batcher::Clock::time_point{} + 1s;
  for (int i = 0; i < 31; ++i) EXPECT_FALSE(b.add(Sample{}, t));
  EXPECT_TRUE(b.add(Sample{}, t));
  EXPECT_EQ(b.take().size(), 32u);
  EXPECT_TRUE(b.empty());
}

TEST(Batcher, DueFiftyMillisecondsAfterTheOldestSample) {
  Batcher b;
  const auto t0 = Batcher::Clock::time_point{} + 1s;
  EXPECT_FALSE(b.due(t0 + 1h));  // nothing pending, nothing due
  b.add(Sample{}, t0);
  b.add(Sample{}, t0 + 40ms);
  EXPECT_FALSE(b.due(t0 + 49ms));
  EXPECT_TRUE(b.due(t0 + 50ms));
}

}  // namespace
}  // namespace plumb::bridge_component
