// Decoding of the records the reader meets in the data section and in the summary.
#pragma once

#include <string>

#include "bytes.hpp"
#include "plumb/mcap/records.hpp"

namespace plumb::mcap::detail {

inline Schema decode_schema(Cursor& c) {
  Schema s;
  s.id = c.get<std::uint16_t>("schema id");
  s.name = c.string("schema name");
  s.encoding = c.string("schema encoding");
  s.data = c.string("schema data");
  return s;
}

inline Channel decode_channel(Cursor& c) {
  Channel ch;
  ch.id = c.get<std::uint16_t>("channel id");
  ch.schema_id = c.get<std::uint16_t>("schema_id");
  ch.topic = c.string("topic");
  ch.message_encoding = c.string("message_encoding");
  ch.metadata = c.map("channel metadata");
  return ch;
}

inline Metadata decode_metadata(Cursor& c) {
  Metadata m;
  m.name = c.string("metadata name");
  m.entries = c.map("metadata");
  return m;
}

inline Statistics decode_statistics(Cursor& c) {
  Statistics s;
  s.message_count = c.get<std::uint64_t>("message_count");
  c.get<std::uint16_t>("schema_count");
  c.get<std::uint32_t>("channel_count");
  c.get<std::uint32_t>("attachment_count");
  s.metadata_count = c.get<std::uint32_t>("metadata_count");
  s.chunk_count = c.get<std::uint32_t>("chunk_count");
  s.message_start_time = c.get<std::uint64_t>("message_start_time");
  s.message_end_time = c.get<std::uint64_t>("message_end_time");
  const auto n = c.get<std::uint32_t>("channel_message_counts");
  Cursor counts(c.take(n, "channel_message_counts"), n);
  while (counts.left() > 0) {
    const auto channel = counts.get<std::uint16_t>("channel id");
    s.channel_message_counts[channel] = counts.get<std::uint64_t>("message count");
  }
  return s;
}

inline std::string opcode_name(std::uint8_t opcode) {
  static const char* const names[] = {"unknown",        "header",     "footer",   "schema",         "channel",
                                      "message",        "chunk",      "message index", "chunk index", "attachment",
                                      "attachment index", "statistics", "metadata", "metadata index", "summary offset",
                                      "data end"};
  if (opcode < sizeof names / sizeof names[0] && opcode != 0) return names[opcode];
  return "unknown (opcode " + std::to_string(opcode) + ")";
}

}  // namespace plumb::mcap::detail
