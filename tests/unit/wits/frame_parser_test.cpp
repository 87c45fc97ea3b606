// The WITS level-0 frame parser: frames in pieces of any size, garbage and cut frames counted,
// random bytes never break it and never hide a good frame that follows them.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "plumb/wits/frame_parser.hpp"

namespace plumb::wits {
namespace {

std::string frame(double bit_depth, double hole_depth) {
  char text[96];
  std::snprintf(text, sizeof text, "&&\r\n0108%.2f\r\n0110%.2f\r\n!!\r\n", bit_depth, hole_depth);
  return text;
}

TEST(WitsFrameParser, ReadsItemsOfAFrame) {
  FrameParser p;
  std::vector<Frame> out;
  p.feed("&&\r\n01081234.56\r\n0110 1240.00 \r\n0112-3.5\r\n!!\r\n", out);
  ASSERT_EQ(out.size(), 1u);
  ASSERT_EQ(out[0].items.size(), 3u);
  EXPECT_EQ(out[0].items[0].code, 108);
  EXPECT_EQ(out[0].items[0].value, "1234.56");
  EXPECT_EQ(out[0].items[1].code, 110);
  EXPECT_EQ(out[0].items[1].value, "1240.00");
  EXPECT_EQ(out[0].items[2].value, "-3.5");
  EXPECT_EQ(p.counters().frames, 1u);
  EXPECT_EQ(p.counters().garbage_bytes, 0u);
}

TEST(WitsFrameParser, FramesArriveInPiecesOfAnySize) {
  std::string stream;
  for (int i = 0; i < 20; ++i) stream += frame(1000 + i, 1001 + i);
  for (std::size_t piece : {1u, 2u, 3u, 7u, 64u}) {
    FrameParser p;
    std::vector<Frame> out;
    for (std::size_t at = 0; at < stream.size(); at += piece) p.feed(stream.substr(at, piece), out);
    ASSERT_EQ(out.size(), 20u) << "pieces of " << piece;
    EXPECT_EQ(out[19].items[0].value, "1019.00");
  }
}

TEST(WitsFrameParser, LineEndingsCrLfCrOrLf) {
  FrameParser p;
  std::vector<Frame> out;
  p.feed("&&\n0108100\n!!\n&&\r0108101\r!!\r&&\r\n0108102\r\n!!\r\n", out);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[2].items[0].value, "102");
}

TEST(WitsFrameParser, GarbageBetweenFramesIsCountedOncePerRun) {
  FrameParser p;
  std::vector<Frame> out;
  p.feed(frame(1, 2) + "noise\r\n\x01\x02\xff\r\n" + frame(3, 4) + "xy" + frame(5, 6), out);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(p.counters().garbage_bytes, 5u + 3u + 2u);
  EXPECT_EQ(p.counters().garbage_runs, 2u);
  EXPECT_EQ(p.counters().cut_frames, 0u);
}

TEST(WitsFrameParser, CutFramesAreCountedAndTheNextFrameKept) {
  FrameParser p;
  std::vector<Frame> out;
  // A frame cut in the middle of a line, then a whole one; a frame whose "!!" never comes.
  p.feed("&&\r\n0108100.00\r\n0110 10", out);
  p.feed(frame(101, 102), out);
  p.feed("&&\r\n0108103.00\r\n", out);
  p.feed(frame(104, 105), out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].items[0].value, "101.00");
  EXPECT_EQ(out[1].items[0].value, "104.00");
  EXPECT_EQ(p.counters().cut_frames, 2u);
}

TEST(WitsFrameParser, TheStreamsEndCutsTheFrameInProgress) {
  FrameParser p;
  std::vector<Frame> out;
  p.feed("&&\r\n0108100.00\r\n", out);
  p.end_of_stream();
  p.feed("0110200\r\n!!\r\n", out);  // the rest, on a new connection: not a frame
  p.feed(frame(1, 2), out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(p.counters().cut_frames, 1u);
  EXPECT_GT(p.counters().garbage_bytes, 0u);
}

TEST(WitsFrameParser, BadLinesInsideAFrameAreCountedTheRestKept) {
  FrameParser p;
  std::vector<Frame> out;
  p.feed("&&\r\n0108100\r\nhello\r\n01X0200\r\n0110300\r\n!!\r\n&&\r\n!!\r\n", out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].items.size(), 2u);
  EXPECT_EQ(p.counters().bad_lines, 2u);
  EXPECT_EQ(p.counters().empty_frames, 1u);
}

TEST(WitsFrameParser, NoiseBeforeTheStartMarkerOnItsLine) {
  FrameParser p;
  std::vector<Frame> out;
  p.feed("zz&&\r\n0108100\r\n!!\r\n", out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(p.counters().garbage_bytes, 2u);
}

TEST(WitsFrameParser, EndlessLinesAndFramesStayBounded) {
  FrameParser p;
  std::vector<Frame> out;
  p.feed(std::string(100000, 'a'), out);
  p.feed("\r\n&&\r\n", out);
  for (int i = 0; i < 2000; ++i) p.feed("0108100\r\n", out);
  EXPECT_EQ(p.counters().cut_frames, 1u);
  p.feed(frame(7, 8), out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(p.counters().garbage_bytes >= 100000u, true);
}

// Fuzz-like: random bytes (and random WITS-looking pieces) between good frames, fed in random
// pieces. Every good frame comes out, in order, whatever came before it, as long as the noise
// ends in a line break (noise that runs into "&&" on the same line is a frame start with noise).
TEST(WitsFrameParser, RandomGarbageNeverHidesAGoodFrame) {
  std::mt19937 rng(26);
  const std::vector<std::string> pieces{"&&", "!!", "\r\n", "0108", "0110", "12.5", "\n", "&", "!", "\x00", "\xff"};
  for (int trial = 0; trial < 200; ++trial) {
    std::string stream;
    std::vector<double> sent;
    for (int f = 0; f < 20; ++f) {
      std::string noise;
      const int n = std::uniform_int_distribution<int>(0, 40)(rng);
      for (int k = 0; k < n; ++k) {
        if (rng() % 2) noise += static_cast<char>(rng() % 256);
        else noise += pieces[rng() % pieces.size()];
      }
      stream += noise + "\r\n";
      sent.push_back(1000 + f);
      stream += frame(sent.back(), sent.back() + 1);
    }
    FrameParser p;
    std::vector<Frame> out;
    for (std::size_t at = 0; at < stream.size();) {
      const std::size_t size = 1 + rng() % 50;
      p.feed(stream.substr(at, size), out);
      at += size;
    }
    std::vector<double> got;
    for (const auto& fr : out) {
      for (const auto& item : fr.items) {
        double v = 0;
        // A frame of noise may also pass ("&&", "0108..", "!!" at random): only the good ones count.
        if (item.code == 108 && parse_value(item.value, v) && v >= 1000 && fr.items.size() == 2) got.push_back(v);
      }
    }
    std::vector<double> good;
    for (double v : got)
      if (good.size() < sent.size() && v == sent[good.size()]) good.push_back(v);
    EXPECT_EQ(good, sent) << "trial " << trial;
  }
}

TEST(WitsFrameParser, ItemCodesAndValues) {
  EXPECT_EQ(parse_item_code("0108"), 108);
  EXPECT_EQ(parse_item_code("108"), -1);
  EXPECT_EQ(parse_item_code("01a8"), -1);
  double v = 0;
  EXPECT_TRUE(parse_value("-12.5", v));
  EXPECT_EQ(v, -12.5);
  EXPECT_FALSE(parse_value("12.5m", v));
  EXPECT_FALSE(parse_value("nan", v));
  EXPECT_FALSE(parse_value("", v));
}

}  // namespace
}  // namespace plumb::wits
