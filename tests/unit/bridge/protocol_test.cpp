#include "plumb/bridge/protocol.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "test_samples.hpp"

namespace plumb::bridge {
namespace {

TEST(Crc32, StandardCheckValue) {
  const std::string check = "123456789";
  EXPECT_EQ(crc32(reinterpret_cast<const std::uint8_t*>(check.data()), check.size()), 0xCBF43926u);
  EXPECT_EQ(crc32(nullptr, 0), 0u);
}

TEST(Crc32, SlicedLoopAgreesWithBytewiseAtEveryLength) {
  // The slicing-by-8 path and the byte tail must agree with the bit-by-bit definition.
  std::vector<std::uint8_t> data(100);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 37 + 11);
  for (std::size_t n = 0; n <= data.size(); ++n) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < n; ++i) {
      c ^= data[i];
      for (int k = 0; k < 8; ++k) c = (c & 1) ? (c >> 1) ^ 0xEDB88320u : c >> 1;
    }
    EXPECT_EQ(crc32(data.data(), n), c ^ 0xFFFFFFFFu) << n;
  }
}

TEST(Frame, LayoutMatchesTheDocumentedTable) {
  Sample s = test::make_sample(0x0102030405060708ull);
  s.t = 1.5;
  s.f = {1.0, 0, 0};
  s.flags = 0xA1B2C3D4u;
  const auto f = encode_frame(s);
  ASSERT_EQ(f.size(), kFrameSizeV1);
  EXPECT_EQ(f[0], 0xA5);
  EXPECT_EQ(f[1], 0x5A);
  EXPECT_EQ(f[2], 1);
  EXPECT_EQ(f[3], 0);
  EXPECT_EQ(f[4], 60);
  EXPECT_EQ(f[5], 0);
  EXPECT_EQ(f[6], 0x08);  // seq, little-endian
  EXPECT_EQ(f[13], 0x01);
  const std::uint64_t ns = 1500000000ull;
  for (int i = 0; i < 8; ++i) EXPECT_EQ(f[14 + i], static_cast<std::uint8_t>(ns >> (8 * i)));
  // fx = 1.0f = 0x3F800000, little-endian
  EXPECT_EQ(f[22], 0x00);
  EXPECT_EQ(f[25], 0x3F);
  EXPECT_EQ(f[24], 0x80);
  EXPECT_EQ(f[62], 0xD4);
  EXPECT_EQ(f[65], 0xA1);
  const std::uint32_t crc = crc32(f.data(), 66);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(f[66 + i], static_cast<std::uint8_t>(crc >> (8 * i)));
}

TEST(Frame, DocumentedExampleIsByteExact) {
  // docs/protocol.md "Example".
  Sample s;
  s.seq = 1;
  s.t = 0.001;
  s.f = {0, 0, -9.81};
  s.b = {20, 0, 40};
  s.temp_c = 25;
  s.flags = 384;
  const std::vector<std::uint8_t> expected = {
      0xA5, 0x5A, 0x01, 0x00, 0x3C, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x40, 0x42, 0x0F, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC3, 0xF5, 0x1C, 0xC1, 0x00, 0x00,
      0xA0, 0x41, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x42, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC8, 0x41, 0x80, 0x01, 0x00, 0x00, 0x38, 0x9A, 0x4A, 0xC9};
  EXPECT_EQ(encode_frame(s), expected);
}

TEST(Frame, RoundTripOfFloat32ExactValuesIsExact) {
  const Sample s = test::make_sample(1234);
  const auto f = encode_frame(s);
  const Sample d = decode_payload_v1(f.data() + kHeaderSize);
  EXPECT_EQ(d.seq, s.seq);
  EXPECT_EQ(d.t, s.t);
  EXPECT_EQ(d.f, s.f);
  EXPECT_EQ(d.b, s.b);
  EXPECT_EQ(d.w, s.w);
  EXPECT_EQ(d.temp_c, s.temp_c);
  EXPECT_EQ(d.flags, s.flags);
}

TEST(Frame, ChannelsAreRoundedToFloat32) {
  Sample s;
  s.f = {0.1, 1e-3, 9.80665};
  const Sample d = decode_payload_v1(encode_frame(s).data() + kHeaderSize);
  for (int i = 0; i < 3; ++i) {
    // float32 keeps 24 significant bits: relative error at most 2^-24.
    EXPECT_NEAR(d.f[i], s.f[i], std::abs(s.f[i]) * std::ldexp(1.0, -24));
    EXPECT_EQ(d.f[i], static_cast<double>(static_cast<float>(s.f[i])));
  }
}

TEST(Frame, NonFiniteTimeIsEncodedAsZeroInsteadOfUndefinedBehaviour) {
  Sample s;
  s.t = std::nan("");
  const Sample d = decode_payload_v1(encode_frame(s).data() + kHeaderSize);
  EXPECT_EQ(d.t, 0.0);
  s.t = 1e300;
  EXPECT_GT(decode_payload_v1(encode_frame(s).data() + kHeaderSize).t, 9e9);
}

TEST(Ascii, HeaderAndLineFollowTheSensorCsv) {
  EXPECT_EQ(ascii_header(), "seq,t,fx,fy,fz,bx,by,bz,wx,wy,wz,temp_c\n");
  const std::string line = encode_ascii_line(test::make_sample(4));
  EXPECT_EQ(line.rfind("4,0.004,", 0), 0u) << line;
  EXPECT_EQ(line.back(), '\n');
  EXPECT_EQ(std::count(line.begin(), line.end(), ','), 11);
}

}  // namespace
}  // namespace plumb::bridge
