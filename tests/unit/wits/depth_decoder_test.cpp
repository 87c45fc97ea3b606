// From WITS frames to the tool's depth: items, feet, the sensor's offset, and the flags.
#include <gtest/gtest.h>

#include <cmath>

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
  DepthDecoder d({});
  EXPECT_FALSE(d.decode(items({{108, "100.00"}}), 0)->moving);
  EXPECT_TRUE(d.decode(items({{108, "100.05"}}), 1)->moving);
  EXPECT_FALSE(d.decode(items({{108, "100.055"}}), 2)->moving);  // within 1 cm
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
