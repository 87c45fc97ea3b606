// Files cut at every byte (a killed recorder, a full disk) and files with flipped bytes: the
// reader never throws, reads every whole chunk before the damage, and names the damage's offset.
#include <gtest/gtest.h>

#include <cstring>

#include "mcap_test_support.hpp"

namespace plumb::mcap::test {
namespace {

TEST(McapDamage, CutAnywhereReadsTheWholeChunksBefore) {
  const auto path = temp_path("whole.mcap");
  write_sample(path, 60, 128);
  const auto bytes = file_bytes(path);
  std::size_t previous = 0;
  const auto cut = temp_path("cut.mcap");
  // Every offset through the header, schema, channel, metadata and the first chunks (every field
  // of each record class), then every 7th byte: a prime stride lands in every field of later records.
  for (std::size_t n = 8; n < bytes.size(); n += (n < 1200 ? 1 : 7)) {
    write_bytes(cut, bytes, n);
    Reader r(cut);
    EXPECT_FALSE(r.has_summary()) << n;
    const auto read = read_all(r);
    // Messages come back in order, with no gap, and more bytes never give fewer messages.
    for (std::size_t i = 0; i < read.size(); ++i) ASSERT_EQ(read[i].payload, i) << "cut at " << n;
    EXPECT_GE(read.size(), previous) << "cut at " << n;
    previous = read.size();
    EXPECT_LE(r.readable_bytes(), n);
  }
  EXPECT_EQ(previous, 60u);  // cut inside the summary: every message is in the data section
  std::filesystem::remove(path);
  std::filesystem::remove(cut);
}

TEST(McapDamage, TruncationIsReportedWithItsOffset) {
  const auto path = temp_path("trunc.mcap");
  write_sample(path, 200, 256);
  auto bytes = file_bytes(path);
  Reader whole(path);
  const auto total = read_all(whole).size();
  write_bytes(path, bytes, bytes.size() / 2);
  Reader r(path);
  const auto read = read_all(r);
  EXPECT_GT(read.size(), 0u);
  EXPECT_LT(read.size(), total);
  ASSERT_EQ(r.problems().size(), 1u);
  EXPECT_NE(r.problems()[0].find("byte " + std::to_string(r.readable_bytes())), std::string::npos) << r.problems()[0];
  EXPECT_NE(r.problems()[0].find("truncated"), std::string::npos) << r.problems()[0];
  std::filesystem::remove(path);
}

TEST(McapDamage, AFlippedByteInAChunkSkipsThatChunkOnly) {
  const auto path = temp_path("flip.mcap");
  write_sample(path, 400, 256, false);  // uncompressed: the flip reaches the CRC check, not zstd
  auto bytes = file_bytes(path);
  // Flip a byte inside the payload of a message far into the file (the 150th payload).
  const std::uint8_t pattern[8] = {150, 0, 0, 0, 0, 0, 0, 0};
  std::size_t at = 0;
  for (std::size_t i = 64; i + 8 < bytes.size(); ++i) {
    if (std::memcmp(bytes.data() + i, pattern, 8) == 0) {
      at = i;
      break;
    }
  }
  ASSERT_GT(at, 0u);
  bytes[at + 3] = static_cast<char>(0x5A);
  write_bytes(path, bytes, bytes.size());
  Reader r(path);
  const auto read = read_all(r);
  EXPECT_LT(read.size(), 400u);
  EXPECT_GT(read.size(), 380u);  // one small chunk lost
  ASSERT_EQ(r.problems().size(), 1u);
  EXPECT_NE(r.problems()[0].find("CRC mismatch"), std::string::npos) << r.problems()[0];
  EXPECT_EQ(r.problems()[0].rfind("byte ", 0), 0u) << r.problems()[0];
  std::filesystem::remove(path);
}

TEST(McapDamage, ACorruptSummaryFallsBackToTheScan) {
  const auto path = temp_path("summary.mcap");
  write_sample(path, 100);
  auto bytes = file_bytes(path);
  bytes[bytes.size() - 8 - 29 - 5] ^= 0x40;  // inside the summary offsets, covered by the summary CRC
  write_bytes(path, bytes, bytes.size());
  Reader r(path);
  EXPECT_FALSE(r.has_summary());
  EXPECT_EQ(read_all(r).size(), 100u);
  EXPECT_EQ(r.statistics().message_count, 100u);
  ASSERT_FALSE(r.problems().empty());
  EXPECT_NE(r.problems()[0].find("summary CRC"), std::string::npos) << r.problems()[0];
  std::filesystem::remove(path);
}

TEST(McapDamage, AFooterPointingOutsideTheSummaryFallsBackToTheScan) {
  const auto path = temp_path("footer.mcap");
  write_sample(path, 50);
  auto bytes = file_bytes(path);
  const std::size_t footer = bytes.size() - 8 - 29;
  for (std::size_t i = 0; i < 8; ++i) bytes[footer + 17 + i] = static_cast<char>(i == 0 ? 1 : 0);  // summary_offset_start = 1
  for (std::size_t i = 0; i < 4; ++i) bytes[footer + 25 + i] = 0;  // summary CRC "not available"
  write_bytes(path, bytes, bytes.size());
  Reader r(path);
  EXPECT_FALSE(r.has_summary());
  EXPECT_EQ(read_all(r).size(), 50u);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace plumb::mcap::test
