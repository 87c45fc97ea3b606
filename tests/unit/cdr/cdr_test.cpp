#include <gtest/gtest.h>

#include <cstring>

#include "plumb/topics/all.hpp"
#include "plumb/topics/cdr.hpp"

namespace plumb::topics {
namespace {

SensorBatch one_sample_batch() {
  SensorBatch b;
  b.tool_id = "T1";
  SensorSample s;
  s.seq = 7;
  s.stamp_ns = -2;
  s.fz = 9.81;
  s.flags = 0x80;
  b.samples.push_back(s);
  return b;
}

std::uint64_t u64_at(const std::vector<std::uint8_t>& b, std::size_t at) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = v << 8 | b[at + static_cast<std::size_t>(i)];
  return v;
}

// The XCDR1 layout worked out by hand from the rules (offsets after the 4-byte header):
// tool_id u32 3 "T1\0" (0..6), calibration_id at 8: u32 1 "\0" (8..12), samples count at 16,
// SensorSample at 24 (8-aligned): seq, stamp_ns, 10 doubles, flags at 120..123.
TEST(Cdr, SensorBatchLayoutIsXcdr1LittleEndian) {
  std::vector<std::uint8_t> b;
  cdr::serialize(one_sample_batch(), b);
  ASSERT_EQ(b.size(), 4u + 124u);
  EXPECT_EQ((std::vector<std::uint8_t>(b.begin(), b.begin() + 4)), (std::vector<std::uint8_t>{0, 1, 0, 0}));
  EXPECT_EQ(b[4], 3);
  EXPECT_EQ(b[8], 'T');
  EXPECT_EQ(b[9], '1');
  EXPECT_EQ(b[10], 0);
  EXPECT_EQ(b[4 + 8], 1);   // calibration_id: length 1, just the NUL
  EXPECT_EQ(b[4 + 16], 1);  // one sample
  EXPECT_EQ(u64_at(b, 4 + 24), 7u);
  EXPECT_EQ(static_cast<std::int64_t>(u64_at(b, 4 + 32)), -2);
  double fz = 0;
  std::memcpy(&fz, b.data() + 4 + 40 + 16, 8);
  EXPECT_EQ(fz, 9.81);
  EXPECT_EQ(b[4 + 120], 0x80);
}

template <class T> void round_trip(const T& m) {
  std::vector<std::uint8_t> b;
  cdr::serialize(m, b);
  T back;
  cdr::deserialize(b.data(), b.size(), back);
  EXPECT_EQ(back, m) << type_support<T>().type_name;
}

template <class... T> void round_trip_defaults(TypeList<T...>) { (round_trip(T{}), ...); }

TEST(Cdr, EveryTypeRoundTrips) {
  round_trip_defaults(AllTypes{});
  round_trip(one_sample_batch());
  Attitude a;
  a.tool_id = "tool";
  a.estimator = "static";
  a.inclination_deg = 1.25;
  a.flags = 3;
  a.reason = "why";
  round_trip(a);
}

TEST(Cdr, ShortMessagesAndBrokenBoundsAreRefused) {
  std::vector<std::uint8_t> b;
  cdr::serialize(one_sample_batch(), b);
  SensorBatch back;
  for (std::size_t n = 0; n < b.size(); ++n) EXPECT_THROW(cdr::deserialize(b.data(), n, back), cdr::Error) << n;
  auto too_many = b;
  too_many[4 + 16] = 33;  // 33 samples > sequence<SensorSample, 32>
  EXPECT_THROW(cdr::deserialize(too_many.data(), too_many.size(), back), cdr::Error);
  auto big_endian = b;
  big_endian[1] = 0;
  EXPECT_THROW(cdr::deserialize(big_endian.data(), big_endian.size(), back), cdr::Error);
}

TEST(Cdr, IdlSourceIsTheSelfContainedIdlOfTheType) {
  const auto text = idl_source<SensorBatch>();
  EXPECT_NE(text.find("struct SensorSample"), std::string_view::npos);
  EXPECT_NE(text.find("struct SensorBatch"), std::string_view::npos);
  EXPECT_EQ(text.find("#include"), std::string_view::npos);
}

}  // namespace
}  // namespace plumb::topics
