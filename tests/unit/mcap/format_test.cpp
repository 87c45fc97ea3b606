// Round trip through the writer and reader: every message, channel, schema and metadata back,
// the summary's statistics equal to what a scan counts, the layout the specification fixes.
#include <gtest/gtest.h>

#include <cstring>

#include "mcap_test_support.hpp"

namespace plumb::mcap::test {
namespace {

TEST(McapFormat, RoundTripEveryMessageInOrder) {
  const auto path = temp_path("roundtrip.mcap");
  write_sample(path, 1000);
  Reader r(path);
  EXPECT_TRUE(r.has_summary());
  EXPECT_EQ(r.statistics().message_count, 1000u);
  EXPECT_GT(r.statistics().chunk_count, 10u);  // 512-byte chunks: many
  EXPECT_EQ(r.statistics().channel_message_counts.at(1), 500u);
  EXPECT_EQ(r.statistics().message_start_time, 1000u);
  EXPECT_EQ(r.statistics().message_end_time, 1999u);
  ASSERT_EQ(r.channels().size(), 2u);
  EXPECT_EQ(r.channels().at(1).metadata.at("qos"), "reliable");
  EXPECT_EQ(r.schemas().at(1).encoding, "omgidl");
  ASSERT_EQ(r.metadata().size(), 1u);
  EXPECT_EQ(r.metadata()[0].entries.at("host"), "test");
  const auto read = read_all(r);
  ASSERT_EQ(read.size(), 1000u);
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read[i].payload, i);
    EXPECT_EQ(read[i].topic, i % 2 ? "plumb/b" : "plumb/a");
  }
  EXPECT_TRUE(r.problems().empty());
  EXPECT_EQ(r.readable_bytes(), r.file_size());
  EXPECT_EQ(r.header().library, "plumb");
  std::filesystem::remove(path);
}

TEST(McapFormat, UncompressedChunksReadTheSame) {
  const auto path = temp_path("plain.mcap");
  write_sample(path, 300, 4096, false);
  Reader r(path);
  EXPECT_EQ(read_all(r).size(), 300u);
  EXPECT_TRUE(r.problems().empty());
  std::filesystem::remove(path);
}

TEST(McapFormat, StartsAndEndsWithTheMagicAndAFooter) {
  const auto path = temp_path("layout.mcap");
  write_sample(path, 10);
  const auto bytes = file_bytes(path);
  ASSERT_GT(bytes.size(), 16u + 29u);
  EXPECT_EQ(std::memcmp(bytes.data(), kMagic, 8), 0);
  EXPECT_EQ(std::memcmp(bytes.data() + bytes.size() - 8, kMagic, 8), 0);
  EXPECT_EQ(static_cast<std::uint8_t>(bytes[8]), kHeader);
  EXPECT_EQ(static_cast<std::uint8_t>(bytes[bytes.size() - 8 - 29]), kFooter);
  std::filesystem::remove(path);
}

TEST(McapFormat, AnEmptyRecordingIsValid) {
  const auto path = temp_path("empty.mcap");
  { Writer w(path); }
  Reader r(path);
  EXPECT_TRUE(r.has_summary());
  EXPECT_EQ(r.statistics().message_count, 0u);
  EXPECT_TRUE(read_all(r).empty());
  EXPECT_TRUE(r.problems().empty());
  std::filesystem::remove(path);
}

TEST(McapFormat, NotAnMcapFileIsRefusedAtByteZero) {
  const auto path = temp_path("not.mcap");
  write_bytes(path, std::vector<char>(100, 'x'), 100);
  try {
    Reader r(path);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("byte 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Reader(temp_path("missing.mcap")), Error);
  std::filesystem::remove(path);
}

TEST(McapFormat, WriterRefusesAPathItCannotCreate) {
  EXPECT_THROW(Writer("/nonexistent-dir/x.mcap"), Error);
}

}  // namespace
}  // namespace plumb::mcap::test
