// The frame a played rig writes reads back through the parser and the decoder: the same depths,
// in metres or feet, and the UTC date and time of the moment given.
#include <gtest/gtest.h>

#include <vector>

#include "plumb/wits/depth_decoder.hpp"
#include "plumb/wits/frame_parser.hpp"
#include "plumb/wits/frame_writer.hpp"

namespace plumb::wits {
namespace {

TEST(WitsFrameWriter, ReadsBackThroughParserAndDecoder) {
  for (const double unit_m : {1.0, kFootInMetres}) {
    // 2026-11-29 01:02:03 UTC.
    const std::string text = record01_frame(1234.5, 1240.25, unit_m, 1795914123);
    FrameParser parser;
    std::vector<Frame> frames;
    parser.feed(text, frames);
    ASSERT_EQ(frames.size(), 1u) << text;
    EXPECT_EQ(parser.counters().garbage_bytes, 0u);
    ASSERT_GE(frames[0].items.size(), 2u);
    EXPECT_EQ(frames[0].items[0].code, 105);
    EXPECT_EQ(frames[0].items[0].value, "261129");
    EXPECT_EQ(frames[0].items[1].code, 106);
    EXPECT_EQ(frames[0].items[1].value, "010203");
    DepthOptions o;
    o.unit_m = unit_m;
    DepthDecoder decoder(o);
    const auto depth = decoder.decode(frames[0], 0);
    ASSERT_TRUE(depth);
    // Two decimals of the feed's unit: within half a hundredth of it.
    EXPECT_NEAR(depth->bit_depth_m, 1234.5, 0.005 * unit_m);
    EXPECT_NEAR(depth->hole_depth_m, 1240.25, 0.005 * unit_m);
  }
}

}  // namespace
}  // namespace plumb::wits
