// The records that the writer puts both in the data section and in the summary, encoded once.
#pragma once

#include "bytes.hpp"
#include "plumb/mcap/records.hpp"

namespace plumb::mcap::detail {

inline Bytes encode_schema(const Schema& s) {
  Bytes out;
  const auto r = begin_record(out, kSchema);
  put<std::uint16_t>(out, s.id);
  put_string(out, s.name);
  put_string(out, s.encoding);
  put_string(out, s.data);  // uint32 length-prefixed bytes: the same layout as a String
  end_record(out, r);
  return out;
}

inline Bytes encode_channel(const Channel& c) {
  Bytes out;
  const auto r = begin_record(out, kChannel);
  put<std::uint16_t>(out, c.id);
  put<std::uint16_t>(out, c.schema_id);
  put_string(out, c.topic);
  put_string(out, c.message_encoding);
  put_map(out, c.metadata);
  end_record(out, r);
  return out;
}

inline Bytes encode_metadata(const Metadata& m) {
  Bytes out;
  const auto r = begin_record(out, kMetadata);
  put_string(out, m.name);
  put_map(out, m.entries);
  end_record(out, r);
  return out;
}

inline Bytes encode_statistics(const Statistics& s, std::size_t schemas, std::size_t channels) {
  Bytes out;
  const auto r = begin_record(out, kStatistics);
  put<std::uint64_t>(out, s.message_count);
  put<std::uint16_t>(out, static_cast<std::uint16_t>(schemas));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(channels));
  put<std::uint32_t>(out, 0);  // attachments
  put<std::uint32_t>(out, s.metadata_count);
  put<std::uint32_t>(out, s.chunk_count);
  put<std::uint64_t>(out, s.message_start_time);
  put<std::uint64_t>(out, s.message_end_time);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(s.channel_message_counts.size() * 10));
  for (const auto& [channel, count] : s.channel_message_counts) {
    put<std::uint16_t>(out, channel);
    put<std::uint64_t>(out, count);
  }
  end_record(out, r);
  return out;
}

}  // namespace plumb::mcap::detail
