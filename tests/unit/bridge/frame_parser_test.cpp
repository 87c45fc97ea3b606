// The frame parser against every kind of bad input of docs/protocol.md: each is counted exactly,
// and no valid frame is ever lost around it, whatever the chunk boundaries.
#include "plumb/bridge/frame_parser.hpp"

#include <gtest/gtest.h>

#include <random>

#include "plumb/bridge/protocol.hpp"
#include "test_samples.hpp"

namespace plumb::bridge {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes frames_of(const std::vector<Sample>& samples) {
  Bytes out;
  for (const auto& s : samples) append_frame(out, s);
  return out;
}

void append(Bytes& to, const Bytes& from) { to.insert(to.end(), from.begin(), from.end()); }

// Garbage free of the sync byte, so it can never look like the start of a frame.
Bytes plain_garbage(std::size_t n, std::uint8_t seed = 1) {
  Bytes g(n);
  for (std::size_t i = 0; i < n; ++i) {
    g[i] = static_cast<std::uint8_t>(seed + 31 * i);
    if (g[i] == kSync0) g[i] = 0x11;
  }
  return g;
}

struct Parsed {
  Counters counters;
  std::vector<Sample> samples;
};

Parsed parse(const Bytes& bytes, std::size_t chunk = 0) {
  Parsed p;
  FrameParser parser(p.counters);
  if (chunk == 0) chunk = bytes.size() + 1;
  for (std::size_t at = 0; at < bytes.size(); at += chunk) {
    const std::size_t n = std::min(chunk, bytes.size() - at);
    parser.feed(std::span(bytes.data() + at, n), p.samples);
  }
  parser.finish();
  return p;
}

std::vector<std::uint64_t> seqs(const std::vector<Sample>& samples) {
  std::vector<std::uint64_t> v;
  for (const auto& s : samples) v.push_back(s.seq);
  return v;
}

std::vector<std::uint64_t> range(std::uint64_t first, std::uint64_t count) {
  std::vector<std::uint64_t> v;
  for (std::uint64_t i = 0; i < count; ++i) v.push_back(first + i);
  return v;
}

void expect_counters(const Counters& c, std::uint64_t ok, std::uint64_t crc, std::uint64_t truncated,
                     std::uint64_t bad_version, std::uint64_t resyncs, std::uint64_t skipped) {
  EXPECT_EQ(c.frames_ok, ok);
  EXPECT_EQ(c.crc_errors, crc);
  EXPECT_EQ(c.truncated, truncated);
  EXPECT_EQ(c.bad_version, bad_version);
  EXPECT_EQ(c.resyncs, resyncs);
  EXPECT_EQ(c.bytes_skipped, skipped);
}

TEST(FrameParser, CleanStreamDecodesEveryFrameAndCountsNothingElse) {
  const auto samples = test::make_samples(0, 50);
  const auto p = parse(frames_of(samples));
  ASSERT_EQ(p.samples.size(), samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    EXPECT_EQ(p.samples[i].seq, samples[i].seq);
    EXPECT_EQ(p.samples[i].f, samples[i].f);
    EXPECT_EQ(p.samples[i].b, samples[i].b);
  }
  expect_counters(p.counters, 50, 0, 0, 0, 0, 0);
}

TEST(FrameParser, ChunkBoundaryAtEveryByteGivesTheSameResult) {
  const auto bytes = frames_of(test::make_samples(0, 3));
  for (std::size_t cut = 0; cut <= bytes.size(); ++cut) {
    Counters c;
    FrameParser parser(c);
    std::vector<Sample> out;
    parser.feed(std::span(bytes.data(), cut), out);
    parser.feed(std::span(bytes.data() + cut, bytes.size() - cut), out);
    parser.finish();
    EXPECT_EQ(seqs(out), range(0, 3)) << "cut at " << cut;
    expect_counters(c, 3, 0, 0, 0, 0, 0);
  }
}

// One stream with every kind of damage; the counters and the samples must not depend on how
// the bytes were chunked.
Bytes damaged_stream() {
  Bytes s = plain_garbage(13);                              // garbage first: resync 1
  append(s, frames_of(test::make_samples(0, 2)));
  Bytes bad = encode_frame(test::make_sample(2));
  bad[30] ^= 0x01;                                          // CRC error: resync 2
  append(s, bad);
  append(s, frames_of(test::make_samples(3, 1)));
  Bytes cut = encode_frame(test::make_sample(4));
  cut.resize(40);                                           // truncated: resync 3
  append(s, cut);
  append(s, frames_of(test::make_samples(5, 1)));
  const Bytes payload(60, 0x42);
  append(s, encode_raw_frame(2, payload));                  // wrong version
  append(s, frames_of(test::make_samples(6, 1)));
  append(s, plain_garbage(7, 9));                           // garbage at the end: resync 4
  return s;
}

TEST(FrameParser, EveryDamageKindCountedOnceWhateverTheChunking) {
  const Bytes stream = damaged_stream();
  for (std::size_t chunk : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{7},
                            std::size_t{64}, std::size_t{69}, std::size_t{70}, std::size_t{71}}) {
    const auto p = parse(stream, chunk);
    EXPECT_EQ(seqs(p.samples), (std::vector<std::uint64_t>{0, 1, 3, 5, 6})) << "chunk " << chunk;
    expect_counters(p.counters, 5, 1, 1, 1, 4, 13 + 70 + 40 + 7);
  }
}

TEST(FrameParser, SplitAtEveryByteOfTheDamagedStream) {
  const Bytes stream = damaged_stream();
  for (std::size_t cut = 0; cut <= stream.size(); ++cut) {
    Counters c;
    FrameParser parser(c);
    std::vector<Sample> out;
    parser.feed(std::span(stream.data(), cut), out);
    parser.feed(std::span(stream.data() + cut, stream.size() - cut), out);
    parser.finish();
    ASSERT_EQ(seqs(out), (std::vector<std::uint64_t>{0, 1, 3, 5, 6})) << "cut at " << cut;
    ASSERT_EQ(c.crc_errors + c.truncated + c.bad_version + c.resyncs, 7u) << "cut at " << cut;
  }
}

TEST(FrameParser, FrameCutAnywhereAfterItsHeaderIsTruncatedAndTheNextFrameSurvives) {
  for (std::size_t keep = kHeaderSize; keep < kFrameSizeV1; ++keep) {
    Bytes s = frames_of(test::make_samples(0, 1));
    Bytes cut = encode_frame(test::make_sample(1));
    cut.resize(keep);
    append(s, cut);
    append(s, frames_of(test::make_samples(2, 2)));
    const auto p = parse(s);
    EXPECT_EQ(seqs(p.samples), (std::vector<std::uint64_t>{0, 2, 3})) << "kept " << keep;
    expect_counters(p.counters, 3, 0, 1, 0, 1, keep);
  }
}

TEST(FrameParser, FrameCutAtTheEndOfTheStreamIsTruncated) {
  Bytes s = frames_of(test::make_samples(0, 1));
  Bytes cut = encode_frame(test::make_sample(1));
  cut.resize(20);
  append(s, cut);
  const auto p = parse(s);
  expect_counters(p.counters, 1, 0, 1, 0, 1, 20);
}

TEST(FrameParser, ValidFrameInsideACorruptedFrameIsKept) {
  // Frame 1 is interrupted by frame 2, then its tail follows: 1 is truncated, 2 survives.
  Bytes s = frames_of(test::make_samples(0, 1));
  const Bytes one = encode_frame(test::make_sample(1));
  append(s, Bytes(one.begin(), one.begin() + 30));
  append(s, frames_of(test::make_samples(2, 1)));
  append(s, Bytes(one.begin() + 30, one.end()));
  append(s, frames_of(test::make_samples(3, 1)));
  const auto p = parse(s);
  EXPECT_EQ(seqs(p.samples), (std::vector<std::uint64_t>{0, 2, 3}));
  EXPECT_EQ(p.counters.truncated, 1u);
  EXPECT_EQ(p.counters.frames_ok, 3u);
  EXPECT_EQ(p.counters.bytes_skipped, 70u);
  EXPECT_EQ(p.counters.resyncs, 2u);
}

TEST(FrameParser, CrcErrorInEveryByteIsCountedAndTheNeighboursSurvive) {
  for (std::size_t at = 2; at < kFrameSizeV1; ++at) {
    if (at == 2 || at == 4 || at == 5) continue;  // version/length damage: no longer a v1 header
    Bytes s = frames_of(test::make_samples(0, 1));
    Bytes bad = encode_frame(test::make_sample(1));
    bad[at] ^= 0x40;
    append(s, bad);
    append(s, frames_of(test::make_samples(2, 1)));
    const auto p = parse(s);
    EXPECT_EQ(seqs(p.samples), (std::vector<std::uint64_t>{0, 2})) << "byte " << at;
    expect_counters(p.counters, 2, 1, 0, 0, 1, 70);
  }
}

TEST(FrameParser, DamagedHeaderIsSkippedAsGarbage) {
  Bytes s = frames_of(test::make_samples(0, 1));
  Bytes bad = encode_frame(test::make_sample(1));
  bad[4] = 0xFF;  // length 0x00FF is not a v1 length
  bad[5] = 0x7F;  // and 0x7FFF is above the maximum payload: not even a header
  append(s, bad);
  append(s, frames_of(test::make_samples(2, 1)));
  const auto p = parse(s);
  EXPECT_EQ(seqs(p.samples), (std::vector<std::uint64_t>{0, 2}));
  expect_counters(p.counters, 2, 0, 0, 0, 1, 70);
}

TEST(FrameParser, UnknownVersionsAreSkippedWholeAndCounted) {
  Bytes s;
  for (std::size_t len : {std::size_t{0}, std::size_t{10}, std::size_t{60}, std::size_t{200}, kMaxPayloadSize}) {
    append(s, encode_raw_frame(7, Bytes(len, 0x33)));
    append(s, frames_of(test::make_samples(len, 1)));
  }
  const auto p = parse(s, 5);
  EXPECT_EQ(seqs(p.samples), (std::vector<std::uint64_t>{0, 10, 60, 200, kMaxPayloadSize}));
  expect_counters(p.counters, 5, 0, 0, 5, 0, 0);
}

TEST(FrameParser, SyncBytesInGarbageDoNotHideFrames) {
  // Garbage made of sync bytes and fake header starts, right before real frames.
  Bytes s = {0xA5, 0xA5, 0x5A, 0xA5, 0x5A, 0x01, 0xA5, 0x5A, 0x01, 0x00, 0x3C};
  append(s, frames_of(test::make_samples(0, 2)));
  append(s, {0xA5, 0x5A, 0x09, 0x00});
  append(s, frames_of(test::make_samples(2, 1)));
  const auto p = parse(s, 3);
  EXPECT_EQ(seqs(p.samples), range(0, 3));
  EXPECT_EQ(p.counters.frames_ok, 3u);
}

TEST(FrameParser, RandomGarbageBetweenFramesNeverCostsAValidFrame) {
  std::mt19937 rng(42);
  Bytes s;
  const std::uint64_t n = 300;
  std::size_t garbage = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::size_t g = rng() % 90;
    for (std::size_t k = 0; k < g; ++k) s.push_back(static_cast<std::uint8_t>(rng()));
    garbage += g;
    append(s, encode_frame(test::make_sample(i)));
  }
  for (std::size_t chunk : {std::size_t{1}, std::size_t{13}, std::size_t{4096}}) {
    const auto p = parse(s, chunk);
    EXPECT_EQ(seqs(p.samples), range(0, n)) << "chunk " << chunk;
    EXPECT_EQ(p.counters.bytes_skipped, garbage);
  }
}

TEST(FrameParser, FinishStartsAFreshStream) {
  Counters c;
  FrameParser parser(c);
  std::vector<Sample> out;
  const Bytes one = encode_frame(test::make_sample(0));
  parser.feed(std::span(one.data(), 30), out);
  parser.finish();  // the device went away mid-frame
  parser.feed(frames_of(test::make_samples(1, 2)), out);
  parser.finish();
  EXPECT_EQ(seqs(out), range(1, 2));
  expect_counters(c, 2, 0, 1, 0, 1, 30);
}

}  // namespace
}  // namespace plumb::bridge
