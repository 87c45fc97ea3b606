// The records of an MCAP file (https://mcap.dev/spec) that plumb writes and reads, as plain data.
// Only what a recording needs: schemas, channels, messages, metadata and the statistics of the
// summary; attachments are skipped when read.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace plumb::mcap {

// Every failure to read or write a file; the text names the file and, when reading, the byte offset.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kAttachment = 0x09,
  kAttachmentIndex = 0x0A,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

// The 8 bytes that open and close every MCAP file.
inline constexpr std::uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

struct Schema {
  std::uint16_t id = 0;  // never 0 in a file
  std::string name;      // "plumb::msg::SensorBatch"
  std::string encoding;  // "omgidl"
  std::string data;      // the IDL text
};

struct Channel {
  std::uint16_t id = 0;
  std::uint16_t schema_id = 0;
  std::string topic;
  std::string message_encoding;  // "cdr"
  std::map<std::string, std::string> metadata;
};

struct Metadata {
  std::string name;
  std::map<std::string, std::string> entries;
};

// A message as read: `data` points into the reader's buffer and lives as long as the callback.
struct MessageView {
  std::uint16_t channel_id = 0;
  std::uint32_t sequence = 0;
  std::uint64_t log_time = 0;      // ns since the epoch: when the recorder received it
  std::uint64_t publish_time = 0;  // ns: the source's own stamp, or log_time
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
};

struct Statistics {
  std::uint64_t message_count = 0;
  std::uint32_t chunk_count = 0;
  std::uint32_t metadata_count = 0;
  std::uint64_t message_start_time = 0;
  std::uint64_t message_end_time = 0;
  std::map<std::uint16_t, std::uint64_t> channel_message_counts;
};

}  // namespace plumb::mcap
