// From WITS frames to the tool's depth: items, feet, the sensor's offset, and the flags.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "plumb/wits/depth_decoder.hpp"

namespace plumb::wits {
namespace {

Frame items(std::initializer_list<std::pair<int, const char*>> list) {
  Frame f;
  for (const auto& [code, value] : list) f.items.push_back({code, value});
  return f;
}

TEST(WitsDepthDecoder, BitDepthLessTheSensorOffset) {
  DepthOptions o;
  o.sensor_offset_m = 12.5;
  DepthDecoder d(o);
  const auto r = d.decode(items({{108, "1000.00"}, {110, "1003.00"}}), 0);
  ASSERT_TRUE(r);
  EXPECT_DOUBLE_EQ(r->depth_m, 987.5);
  EXPECT_DOUBLE_EQ(r->bit_depth_m, 1000);
  EXPECT_DOUBLE_EQ(r->hole_depth_m, 1003);
  EXPECT_FALSE(r->moving);
}

TEST(WitsDepthDecoder, FeetAreConverted) {
  DepthOptions o;
  o.unit_m = kFootInMetres;
  DepthDecoder d(o);
  const auto r = d.decode(items({{108, "10000"}}), 0);
  ASSERT_TRUE(r);
  EXPECT_DOUBLE_EQ(r->depth_m, 3048);
  EXPECT_TRUE(std::isnan(r->hole_depth_m));
}

TEST(WitsDepthDecoder, FramesWithoutABitDepthAreCounted) {
  DepthDecoder d({});
  EXPECT_FALSE(d.decode(items({{110, "1000"}}), 0));
  EXPECT_FALSE(d.decode(items({{108, "abc"}}), 1));
  EXPECT_EQ(d.counters().frames_without_depth, 2u);
  EXPECT_EQ(d.counters().bad_values, 1u);
  EXPECT_EQ(d.counters().depths, 0u);
}

TEST(WitsDepthDecoder, OtherItemsCarryTheDepthWhenMapped) {
  DepthOptions o;
  o.bit_item = 111;
  DepthDecoder d(o);
  const auto r = d.decode(items({{108, "1"}, {111, "2"}}), 0);
  ASSERT_TRUE(r);
  EXPECT_DOUBLE_EQ(r->depth_m, 2);
}

TEST(WitsDepthDecoder, MovingFromTheDepthItself) {
  DepthOptions o;
  o.moving_window_s = 0;  // the step between two frames alone
  DepthDecoder d(o);
  EXPECT_FALSE(d.decode(items({{108, "100.00"}}), 0)->moving);
  EXPECT_TRUE(d.decode(items({{108, "100.05"}}), 1)->moving);
  EXPECT_FALSE(d.decode(items({{108, "100.055"}}), 2)->moving);  // within 1 cm
}

// Drilling at 30 m/h with a frame a second: 8 mm steps, each under the 1 cm tolerance, are motion
// by their trend over the window; a stop is still once the window has held still.
TEST(WitsDepthDecoder, SlowDrillingIsMovingByItsTrend) {
  DepthDecoder d({});
  const double rate_mps = 30.0 / 3600;
  int moving = 0;
  double depth = 1000;
  for (int t = 0; t <= 60; ++t, depth += rate_mps) {
    const auto r = d.decode(items({{108, std::to_string(depth).c_str()}}), t);
    ASSERT_TRUE(r);
    if (t >= 2) {
      EXPECT_TRUE(r->moving) << "t " << t;
    }
    moving += r->moving;
  }
  EXPECT_GE(moving, 59);
  const std::string stopped = std::to_string(depth);
  bool still_after_window = false;
  for (int t = 61; t <= 70; ++t) {
    const auto r = d.decode(items({{108, stopped.c_str()}}), t);
    if (t >= 61 + 6) still_after_window = !r->moving;
  }
  EXPECT_TRUE(still_after_window);
  // The same steps with no window: never moving (what the depth used to say).
  DepthOptions step_only;
  step_only.moving_window_s = 0;
  DepthDecoder old(step_only);
  depth = 1000;
  int old_moving = 0;
  for (int t = 0; t <= 60; ++t, depth += rate_mps) old_moving += old.decode(items({{108, std::to_string(depth).c_str()}}), t)->moving;
  EXPECT_EQ(old_moving, 0);
}

// Depths a rig cannot report are refused and counted, never published.
TEST(WitsDepthDecoder, ImpossibleDepthsAreRefused) {
  DepthDecoder d({});
  EXPECT_FALSE(d.decode(items({{108, "-5"}}), 0));
  EXPECT_FALSE(d.decode(items({{108, "1e308"}}), 1));
  EXPECT_FALSE(d.decode(items({{108, "16000"}}), 2));
  EXPECT_EQ(d.counters().out_of_range, 3u);
  EXPECT_EQ(d.counters().depths, 0u);
  EXPECT_TRUE(d.decode(items({{108, "-0.5"}}), 3));  // the bit just above the rig floor
  EXPECT_TRUE(d.decode(items({{108, "0"}}), 4));
}

// A depth that jumps faster than a rig moves is refused; one spike is forgotten, a new level that
// holds for three frames is taken (a feed reset, a depth corrected at the rig).
TEST(WitsDepthDecoder, JumpsAreRefusedUntilANewLevelHolds) {
  DepthDecoder d({});
  ASSERT_TRUE(d.decode(items({{108, "1000"}}), 0));
  EXPECT_FALSE(d.decode(items({{108, "5000"}}), 1));  // a spike
  const auto back = d.decode(items({{108, "1000.5"}}), 2);
  ASSERT_TRUE(back);
  EXPECT_DOUBLE_EQ(back->bit_depth_m, 1000.5);
  EXPECT_FALSE(d.decode(items({{108, "2000"}}), 3));
  EXPECT_FALSE(d.decode(items({{108, "2000"}}), 4));
  const auto level = d.decode(items({{108, "2000"}}), 5);
  ASSERT_TRUE(level);
  EXPECT_DOUBLE_EQ(level->bit_depth_m, 2000);
  EXPECT_EQ(d.counters().jumps, 3u);
  EXPECT_TRUE(d.decode(items({{108, "2001"}}), 6));  // from the new level on
  // A trip at 1.5 m/s is no jump.
  DepthDecoder trip({});
  for (int t = 0; t < 20; ++t) ASSERT_TRUE(trip.decode(items({{108, std::to_string(500 + 1.5 * t).c_str()}}), t)) << t;
  EXPECT_EQ(trip.counters().jumps, 0u);
}

TEST(WitsDepthDecoder, InSlipsFromTheDepthItself) {
  DepthDecoder d({});  // still 10 s with the bit 0.5 m off bottom
  EXPECT_FALSE(d.decode(items({{108, "99.00"}, {110, "100"}}), 0)->in_slips);
  EXPECT_FALSE(d.decode(items({{108, "99.00"}, {110, "100"}}), 9)->in_slips);
  EXPECT_TRUE(d.decode(items({{108, "99.00"}, {110, "100"}}), 10)->in_slips);
  EXPECT_FALSE(d.decode(items({{108, "99.50"}, {110, "100"}}), 11)->in_slips);  // moved
  DepthDecoder on_bottom({});
  EXPECT_FALSE(on_bottom.decode(items({{108, "99.80"}, {110, "100"}}), 0)->in_slips);
  EXPECT_FALSE(on_bottom.decode(items({{108, "99.80"}, {110, "100"}}), 30)->in_slips);
}

TEST(WitsDepthDecoder, FlagsFromTheRigsItemsWin) {
  DepthOptions o;
  o.moving_item = 150;
  o.slips_item = 151;
  DepthDecoder d(o);
  auto r = d.decode(items({{108, "100"}, {150, "1"}, {151, "0"}}), 0);
  EXPECT_TRUE(r->moving);
  EXPECT_FALSE(r->in_slips);
  r = d.decode(items({{108, "105"}, {150, "0"}, {151, "1"}}), 1);
  EXPECT_FALSE(r->moving);
  EXPECT_TRUE(r->in_slips);
  r = d.decode(items({{108, "110"}}), 2);  // items not sent: derived
  EXPECT_TRUE(r->moving);
}

TEST(WitsDepthDecoder, ItemCodeOptions) {
  EXPECT_EQ(item_code_option("0108", "--bit-item"), 108);
  EXPECT_EQ(item_code_option("108", "--bit-item"), 108);
  EXPECT_THROW(item_code_option("8", "--bit-item"), std::invalid_argument);
  EXPECT_THROW(item_code_option("01x8", "--bit-item"), std::invalid_argument);
}

}  // namespace
}  // namespace plumb::wits
