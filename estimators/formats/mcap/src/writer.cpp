#include "plumb/mcap/writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <vector>

#include "bytes.hpp"
#include "compression.hpp"
#include "crc32.hpp"
#include "record_encoding.hpp"

namespace plumb::mcap {

using detail::Bytes;
using detail::put;
using detail::put_string;

struct Writer::State {
  std::string path;
  WriterOptions options;
  int fd = -1;
  std::uint64_t offset = 0;     // bytes in the file, all of them whole records
  std::uint32_t data_crc = 0;   // CRC of the data section so far (for the Data End record)
  std::string failure;          // the first write error; the file is then finished best-effort
  bool closed = false;

  std::vector<Schema> schemas;
  std::vector<Channel> channels;
  Statistics stats;
  std::vector<Bytes> chunk_indexes;  // encoded Chunk Index records
  std::vector<Bytes> metadata_indexes;

  // The open chunk: its records uncompressed, per-channel (log_time, offset) and counts.
  Bytes chunk;
  std::uint64_t chunk_start = 0, chunk_end = 0;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index;
  Bytes compressed, out;  // reused buffers

  // Writes `bytes` whole or throws; the offset and the data CRC move only on success, so after
  // an error the file can be cut back to `offset` and still be a sequence of whole records.
  void append(const Bytes& bytes, bool data_section = true) {
    if (!failure.empty()) throw Error(failure);
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        failure = path + ": cannot write at byte " + std::to_string(offset + done) + ": " +
                  (n < 0 ? std::strerror(errno) : "nothing written");
        throw Error(failure);
      }
      done += static_cast<std::size_t>(n);
    }
    if (data_section) data_crc = detail::crc32(data_crc, bytes.data(), bytes.size());
    offset += bytes.size();
  }

  void write_chunk() {
    if (chunk.empty()) return;
    const std::uint32_t crc = detail::crc32(0, chunk.data(), chunk.size());
    const std::string compression = options.compress ? "zstd" : "";
    const Bytes* records = &chunk;
    if (options.compress) {
      detail::zstd_compress(chunk.data(), chunk.size(), options.zstd_level, compressed);
      records = &compressed;
    }
    out.clear();
    const std::uint64_t chunk_offset = offset;
    const auto at = detail::begin_record(out, kChunk);
    put<std::uint64_t>(out, chunk_start);
    put<std::uint64_t>(out, chunk_end);
    put<std::uint64_t>(out, chunk.size());
    put<std::uint32_t>(out, crc);
    put_string(out, compression);
    put<std::uint64_t>(out, records->size());
    detail::put_raw(out, records->data(), records->size());
    detail::end_record(out, at);
    const std::uint64_t chunk_length = out.size();
    std::map<std::uint16_t, std::uint64_t> index_offsets;
    std::uint64_t messages = 0;
    for (const auto& [channel, entries] : chunk_index) {
      index_offsets[channel] = chunk_offset + out.size();
      const auto m = detail::begin_record(out, kMessageIndex);
      put<std::uint16_t>(out, channel);
      put<std::uint32_t>(out, static_cast<std::uint32_t>(entries.size() * 16));
      for (const auto& [time, where] : entries) {
        put<std::uint64_t>(out, time);
        put<std::uint64_t>(out, where);
      }
      detail::end_record(out, m);
      messages += entries.size();
    }
    append(out);
    // Written: now it counts.
    Bytes ci;
    const auto c = detail::begin_record(ci, kChunkIndex);
    put<std::uint64_t>(ci, chunk_start);
    put<std::uint64_t>(ci, chunk_end);
    put<std::uint64_t>(ci, chunk_offset);
    put<std::uint64_t>(ci, chunk_length);
    put<std::uint32_t>(ci, static_cast<std::uint32_t>(index_offsets.size() * 10));
    for (const auto& [channel, where] : index_offsets) {
      put<std::uint16_t>(ci, channel);
      put<std::uint64_t>(ci, where);
    }
    put<std::uint64_t>(ci, out.size() - chunk_length);
    put_string(ci, compression);
    put<std::uint64_t>(ci, records->size());
    put<std::uint64_t>(ci, chunk.size());
    detail::end_record(ci, c);
    chunk_indexes.push_back(std::move(ci));
    if (stats.message_count == 0 || chunk_start < stats.message_start_time) stats.message_start_time = chunk_start;
    stats.message_end_time = std::max(stats.message_end_time, chunk_end);
    stats.message_count += messages;
    for (const auto& [channel, entries] : chunk_index) stats.channel_message_counts[channel] += entries.size();
    ++stats.chunk_count;
    chunk.clear();
    chunk_index.clear();
  }

  void finish() {
    Bytes tail;
    const auto d = detail::begin_record(tail, kDataEnd);
    put<std::uint32_t>(tail, data_crc);
    detail::end_record(tail, d);
    const std::uint64_t summary_start = offset + tail.size();
    struct Group {
      std::uint8_t opcode;
      std::uint64_t start, length;
    };
    std::vector<Group> groups;
    const auto group = [&](std::uint8_t opcode, const std::vector<Bytes>& records) {
      if (records.empty()) return;
      const std::uint64_t start = offset + tail.size();
      for (const auto& r : records) detail::put_raw(tail, r.data(), r.size());
      groups.push_back({opcode, start, offset + tail.size() - start});
    };
    std::vector<Bytes> schema_records, channel_records;
    for (const auto& s : schemas) schema_records.push_back(detail::encode_schema(s));
    for (const auto& ch : channels) channel_records.push_back(detail::encode_channel(ch));
    group(kSchema, schema_records);
    group(kChannel, channel_records);
    group(kStatistics, {detail::encode_statistics(stats, schemas.size(), channels.size())});
    group(kChunkIndex, chunk_indexes);
    group(kMetadataIndex, metadata_indexes);
    const std::uint64_t summary_offset_start = offset + tail.size();
    for (const auto& g : groups) {
      const auto r = detail::begin_record(tail, kSummaryOffset);
      put<std::uint8_t>(tail, g.opcode);
      put<std::uint64_t>(tail, g.start);
      put<std::uint64_t>(tail, g.length);
      detail::end_record(tail, r);
    }
    const std::size_t summary_at = summary_start - offset;
    // The footer's length is written out, not filled in afterwards: the summary CRC covers it.
    put<std::uint8_t>(tail, kFooter);
    put<std::uint64_t>(tail, 20);
    put<std::uint64_t>(tail, summary_start);
    put<std::uint64_t>(tail, summary_offset_start);
    put<std::uint32_t>(tail, detail::crc32(0, tail.data() + summary_at, tail.size() - summary_at));
    detail::put_raw(tail, kMagic, sizeof kMagic);
    append(tail, false);
  }
};

Writer::Writer(const std::string& path, const WriterOptions& options) : s_(std::make_unique<State>()) {
  s_->path = path;
  s_->options = options;
  s_->fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (s_->fd < 0) throw Error("cannot create '" + path + "': " + std::strerror(errno));
  Bytes head(kMagic, kMagic + sizeof kMagic);
  const auto h = detail::begin_record(head, kHeader);
  put_string(head, options.profile);
  put_string(head, options.library);
  detail::end_record(head, h);
  s_->append(head);
}

Writer::~Writer() {
  try {
    close();
  } catch (const Error&) {
    // Reported by close() to callers that call it; a destructor cannot.
  }
}

std::uint16_t Writer::add_schema(const std::string& name, const std::string& encoding, const std::string& data) {
  Schema s{static_cast<std::uint16_t>(s_->schemas.size() + 1), name, encoding, data};
  s_->append(detail::encode_schema(s));
  s_->schemas.push_back(std::move(s));
  return s_->schemas.back().id;
}

std::uint16_t Writer::add_channel(std::uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                                  const std::map<std::string, std::string>& metadata) {
  Channel c{static_cast<std::uint16_t>(s_->channels.size() + 1), schema_id, topic, message_encoding, metadata};
  // Ahead of the open chunk: write it first so the file order stays schema, channel, messages.
  s_->append(detail::encode_channel(c));
  s_->channels.push_back(std::move(c));
  return s_->channels.back().id;
}

void Writer::write(const MessageView& m) {
  auto& s = *s_;
  if (!s.failure.empty()) throw Error(s.failure);
  if (s.chunk.empty()) {
    s.chunk_start = m.log_time;
    s.chunk_end = m.log_time;
  }
  s.chunk_start = std::min(s.chunk_start, m.log_time);
  s.chunk_end = std::max(s.chunk_end, m.log_time);
  s.chunk_index[m.channel_id].emplace_back(m.log_time, s.chunk.size());
  const auto r = detail::begin_record(s.chunk, kMessage);
  put<std::uint16_t>(s.chunk, m.channel_id);
  put<std::uint32_t>(s.chunk, m.sequence);
  put<std::uint64_t>(s.chunk, m.log_time);
  put<std::uint64_t>(s.chunk, m.publish_time);
  detail::put_raw(s.chunk, m.data, m.size);
  detail::end_record(s.chunk, r);
  if (s.chunk.size() >= s.options.chunk_size) s.write_chunk();
}

void Writer::write_metadata(const Metadata& metadata) {
  const std::uint64_t at = s_->offset;
  const Bytes record = detail::encode_metadata(metadata);
  s_->append(record);
  Bytes index;
  const auto r = detail::begin_record(index, kMetadataIndex);
  put<std::uint64_t>(index, at);
  put<std::uint64_t>(index, record.size());
  put_string(index, metadata.name);
  detail::end_record(index, r);
  s_->metadata_indexes.push_back(std::move(index));
  ++s_->stats.metadata_count;
}

void Writer::flush() { s_->write_chunk(); }

void Writer::close() {
  auto& s = *s_;
  if (s.closed) return;
  s.closed = true;
  try {
    s.write_chunk();
  } catch (const Error&) {
    // Reported below; the file is still finished if the disk allows.
  }
  const std::string first_failure = s.failure;
  if (!first_failure.empty()) {
    // A partial write may have left bytes after the last whole record: cut them, which also frees
    // the space the summary needs.
    if (::ftruncate(s.fd, static_cast<off_t>(s.offset)) != 0) {
      // Nothing more to do: the reader skips a torn record at the end.
    }
    ::lseek(s.fd, static_cast<off_t>(s.offset), SEEK_SET);
    s.failure.clear();
  }
  try {
    s.finish();
  } catch (const Error&) {
    if (::ftruncate(s.fd, static_cast<off_t>(s.offset)) != 0) {
      // As above.
    }
  }
  const std::string finish_failure = s.failure;
  if (::close(s.fd) != 0 && first_failure.empty() && finish_failure.empty())
    s.failure = s.path + ": cannot close: " + std::strerror(errno);
  s.fd = -1;
  if (!first_failure.empty()) {
    s.failure = first_failure;
    throw Error(first_failure + (finish_failure.empty() ? " (file closed with a summary: valid)"
                                                          : " (file ends after its last whole chunk: readable)"));
  }
  if (!s.failure.empty()) throw Error(s.failure);
}

const Statistics& Writer::statistics() const { return s_->stats; }
std::uint64_t Writer::bytes_written() const { return s_->offset; }
const std::string& Writer::path() const { return s_->path; }

}  // namespace plumb::mcap
