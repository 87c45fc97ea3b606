// ASCII line mode and the CSV reader's errors: bad lines are counted and named by line and
// column, good lines around them are kept, whatever the chunking.
#include "plumb/bridge/line_parser.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "plumb/bridge/protocol.hpp"
#include "plumb/bridge/stream_parser.hpp"
#include "test_samples.hpp"

namespace plumb::bridge {
namespace {

std::vector<std::uint8_t> bytes_of(const std::string& s) { return {s.begin(), s.end()}; }

struct ParsedLines {
  Counters counters;
  std::vector<Sample> samples;
  std::string last_error;
};

ParsedLines parse_lines(const std::string& text, std::size_t chunk) {
  ParsedLines p;
  LineParser parser(p.counters);
  const auto bytes = bytes_of(text);
  for (std::size_t at = 0; at < bytes.size(); at += chunk) {
    parser.feed(std::span(bytes.data() + at, std::min(chunk, bytes.size() - at)), p.samples);
  }
  parser.finish(p.samples);
  p.last_error = parser.last_error();
  return p;
}

TEST(LineParser, EncodedLinesRoundTripAtAnyChunking) {
  std::string text = ascii_header();
  for (const auto& s : test::make_samples(0, 20)) text += encode_ascii_line(s);
  for (std::size_t chunk : {std::size_t{1}, std::size_t{5}, std::size_t{64}, text.size()}) {
    const auto p = parse_lines(text, chunk);
    ASSERT_EQ(p.samples.size(), 20u);
    for (std::size_t i = 0; i < 20; ++i) {
      const Sample want = test::make_sample(i);
      EXPECT_EQ(p.samples[i].seq, want.seq);
      // The sensor CSV writes t with 12 significant digits: relative rounding below 5e-13.
      EXPECT_NEAR(p.samples[i].t, want.t, 5e-13 * want.t);
      EXPECT_EQ(p.samples[i].f, want.f);
      EXPECT_EQ(p.samples[i].w, want.w);
      EXPECT_EQ(p.samples[i].temp_c, want.temp_c);
      EXPECT_TRUE(p.samples[i].flags & flags::kHasGyro);
    }
    EXPECT_EQ(p.counters.lines_ok, 20u);
    EXPECT_EQ(p.counters.csv_errors, 0u);
  }
}

TEST(LineParser, BadNumberNamesLineAndColumnAndParsingGoesOn) {
  const std::string text =
      "# board v3\n"
      "t,fx,fy,fz,bx,by,bz\n"
      "0.0,1,2,3,4,5,6\n"
      "0.1,1,abc,3,4,5,6\n"
      "0.2,1,2,3,4,5,6\n";
  const auto p = parse_lines(text, 3);
  EXPECT_EQ(p.samples.size(), 2u);
  EXPECT_EQ(p.counters.csv_errors, 1u);
  EXPECT_EQ(p.counters.lines_ok, 2u);
  EXPECT_EQ(p.last_error, "serial:4: column 'fy': bad number 'abc'");
}

TEST(LineParser, MissingColumnNamesTheFirstMissingOne) {
  const auto p = parse_lines("t,fx,fy,fz,bx,by,bz\n0.0,1,2,3,4\n0.1,1,2,3,4,5,6\n", 7);
  EXPECT_EQ(p.samples.size(), 1u);
  EXPECT_EQ(p.counters.csv_errors, 1u);
  EXPECT_NE(p.last_error.find("serial:2: column 'by'"), std::string::npos) << p.last_error;
}

TEST(LineParser, HeaderWithoutRequiredColumnsIsAnErrorAndItsRowsAreDropped) {
  const auto p = parse_lines("t,fx,fy,bx,by,bz\n0,1,2,3,4,5\n", 100);
  EXPECT_TRUE(p.samples.empty());
  EXPECT_EQ(p.counters.csv_errors, 2u);  // the header, then a row with no usable header
  EXPECT_NE(p.last_error.find("before any header"), std::string::npos) << p.last_error;
}

TEST(LineParser, DataBeforeHeaderAndOverlongNoiseAreCounted) {
  std::string text = "1,2,3\n";
  text += std::string(3000, 'x') + "\n";
  text += ascii_header() + encode_ascii_line(test::make_sample(7));
  const auto p = parse_lines(text, 100);
  ASSERT_EQ(p.samples.size(), 1u);
  EXPECT_EQ(p.samples[0].seq, 7u);
  EXPECT_EQ(p.counters.csv_errors, 2u);
}

TEST(LineParser, NewHeaderMidStreamReplacesTheOldOne) {
  const auto p = parse_lines("t,fx,fy,fz,bx,by,bz\n0,1,2,3,4,5,6\nbz,by,bx,fz,fy,fx,t\n6,5,4,3,2,1,0.5\n", 4);
  ASSERT_EQ(p.samples.size(), 2u);
  EXPECT_EQ(p.samples[1].t, 0.5);
  EXPECT_EQ(p.samples[1].f.x(), 1.0);
  EXPECT_EQ(p.samples[1].b.z(), 6.0);
}

TEST(LineParser, NanAndInfAreKeptAndFlagged) {
  const auto p = parse_lines("t,fx,fy,fz,bx,by,bz\n0,nan,2,3,4,5,6\n0.1,1,2,3,4,inf,6\n", 100);
  ASSERT_EQ(p.samples.size(), 2u);
  EXPECT_TRUE(p.samples[0].flags & flags::kNotFinite);
  EXPECT_TRUE(p.samples[1].flags & flags::kNotFinite);
  EXPECT_EQ(p.counters.csv_errors, 0u);
}

TEST(SensorReader, ErrorNamesLineAndColumnAndTheReaderContinues) {
  std::istringstream in("t,fx,fy,fz,bx,by,bz\n0,1,2,3,4,5,6\n0.1,1,2,3,4,5,\n0.2,1,2,3,4,5,6\n");
  csv::SensorReader reader(in, "f.csv");
  Sample s;
  ASSERT_TRUE(reader.next(s));
  try {
    reader.next(s);
    FAIL() << "an empty field must throw";
  } catch (const csv::Error& e) {
    EXPECT_EQ(e.line, 3u);
    EXPECT_EQ(e.column, "bz");
    EXPECT_NE(std::string(e.what()).find("f.csv:3"), std::string::npos);
  }
  ASSERT_TRUE(reader.next(s));
  EXPECT_EQ(s.t, 0.2);
  EXPECT_FALSE(reader.next(s));
}

TEST(SensorReader, SequenceNumberBeyond64BitsIsAnErrorNotOverflow) {
  // Found by tests/fuzz: converting 7.8e71 to uint64 was undefined behaviour.
  std::istringstream in("seq,t,fx,fy,fz,bx,by,bz\n7.8e71,0,1,2,3,4,5,6\n18446744073709551615,0,1,2,3,4,5,6\n");
  csv::SensorReader reader(in, "f.csv");
  Sample s;
  try {
    reader.next(s);
    FAIL() << "seq 7.8e71 must throw";
  } catch (const csv::Error& e) {
    EXPECT_EQ(e.column, "seq");
    EXPECT_EQ(e.line, 2u);
  }
  // 2^64 - 1 reads as the double 2^64: also out of range.
  EXPECT_THROW(reader.next(s), csv::Error);
}

TEST(StreamParser, AutoModeDetectsBinary) {
  Counters c;
  StreamParser parser(c, Mode::Auto);
  std::vector<std::uint8_t> bytes = {0x01, 0x02, 0x03};
  for (const auto& s : test::make_samples(0, 3)) append_frame(bytes, s);
  std::vector<Sample> out;
  for (auto b : bytes) parser.feed(std::span(&b, 1), out);
  parser.finish(out);
  EXPECT_EQ(parser.mode(), Mode::Binary);
  EXPECT_EQ(out.size(), 3u);
  EXPECT_EQ(c.frames_ok, 3u);
  EXPECT_EQ(c.bytes_skipped, 3u);
  EXPECT_EQ(c.csv_errors, 0u);
}

TEST(StreamParser, AutoModeDetectsAscii) {
  Counters c;
  StreamParser parser(c, Mode::Auto);
  std::string text = "# hello\n" + ascii_header();
  for (const auto& s : test::make_samples(0, 4)) text += encode_ascii_line(s);
  std::vector<Sample> out;
  parser.feed(bytes_of(text), out);
  parser.finish(out);
  EXPECT_EQ(parser.mode(), Mode::Ascii);
  EXPECT_EQ(out.size(), 4u);
  EXPECT_EQ(c.lines_ok, 4u);
  EXPECT_EQ(c.frames_ok, 0u);
  EXPECT_EQ(c.bytes_skipped, 0u);
}

TEST(StreamParser, ModeNames) {
  EXPECT_EQ(parse_mode("binary"), Mode::Binary);
  EXPECT_EQ(parse_mode("ascii"), Mode::Ascii);
  EXPECT_EQ(parse_mode("auto"), Mode::Auto);
  EXPECT_FALSE(parse_mode("hex").has_value());
}

}  // namespace
}  // namespace plumb::bridge
