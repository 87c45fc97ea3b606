#include "plumb/mcap/reader.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "bytes.hpp"
#include "compression.hpp"
#include "crc32.hpp"
#include "record_decoding.hpp"

namespace plumb::mcap {

using detail::Cursor;
using detail::ShortRead;

namespace {
constexpr std::size_t kRecordHeader = 9;  // opcode + uint64 length
constexpr std::size_t kFooterRecord = kRecordHeader + 20;
}  // namespace

struct Reader::State {
  std::string path;
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
  bool summary = false;
  Statistics stats;
  std::map<std::uint16_t, Schema> schemas;
  std::map<std::uint16_t, Channel> channels;
  std::vector<Metadata> metadata;
  Header header;
  std::vector<std::string> problems;
  std::vector<std::string> summary_problems;  // found when opening (a summary CRC that fails)
  std::uint64_t readable = 0;
  std::vector<std::uint8_t> chunk;  // decompressed records, reused

  void problem(std::uint64_t offset, const std::string& what) {
    problems.push_back("byte " + std::to_string(offset) + ": " + what);
  }

  // The summary through the footer; false (and the reader scans instead) when anything is off.
  bool read_summary() {
    if (size < sizeof kMagic * 2 + kFooterRecord) return false;
    if (std::memcmp(data + size - sizeof kMagic, kMagic, sizeof kMagic) != 0) return false;
    const std::size_t footer_at = size - sizeof kMagic - kFooterRecord;
    Cursor footer(data + footer_at, kFooterRecord);
    try {
      if (footer.get<std::uint8_t>("opcode") != kFooter || footer.get<std::uint64_t>("length") != 20) return false;
      const auto summary_start = footer.get<std::uint64_t>("summary_start");
      const auto summary_offset_start = footer.get<std::uint64_t>("summary_offset_start");
      const auto crc = footer.get<std::uint32_t>("summary_crc");
      if (summary_start == 0 || summary_start > footer_at) return false;
      if (summary_offset_start != 0 && (summary_offset_start < summary_start || summary_offset_start > footer_at)) return false;
      if (crc != 0) {
        const std::uint32_t computed = detail::crc32(0, data + summary_start, footer_at + kRecordHeader + 16 - summary_start);
        if (computed != crc) {
          problem(summary_start, "summary CRC mismatch (stored " + std::to_string(crc) + ", computed " +
                                     std::to_string(computed) + "): summary ignored, file scanned");
          return false;
        }
      }
      const std::size_t end = summary_offset_start ? summary_offset_start : footer_at;
      Cursor c(data + summary_start, end - summary_start);
      while (c.left() > 0) {
        const auto opcode = c.get<std::uint8_t>("opcode");
        const auto length = c.get<std::uint64_t>("length");
        Cursor body(c.take(length, "record"), length);
        switch (opcode) {
          case kSchema: {
            auto s = detail::decode_schema(body);
            schemas[s.id] = std::move(s);
            break;
          }
          case kChannel: {
            auto ch = detail::decode_channel(body);
            channels[ch.id] = std::move(ch);
            break;
          }
          case kStatistics: stats = detail::decode_statistics(body); break;
          case kMetadataIndex: {
            const auto at = body.get<std::uint64_t>("offset");
            const auto len = body.get<std::uint64_t>("length");
            if (at > size || len > size - at || len < kRecordHeader) return false;
            Cursor record(data + at + kRecordHeader, len - kRecordHeader);
            metadata.push_back(detail::decode_metadata(record));
            break;
          }
          default: break;  // chunk indexes and others: the scan does not need them
        }
      }
    } catch (const ShortRead&) {
      return false;
    }
    return true;
  }

  // The records of one chunk, already decompressed into `chunk`.
  void scan_chunk(std::uint64_t chunk_at, const MessageCallback& on_message) {
    Cursor c(chunk.data(), chunk.size());
    while (c.left() > 0) {
      const std::size_t inner = static_cast<std::size_t>(c.position() - chunk.data());
      try {
        const auto opcode = c.get<std::uint8_t>("opcode");
        const auto length = c.get<std::uint64_t>("length");
        Cursor body(c.take(length, "record"), length);
        on_record(opcode, body, chunk_at, on_message);
      } catch (const ShortRead& e) {
        problem(chunk_at, "chunk record torn at offset " + std::to_string(inner) + " of its records (" + e.field +
                              "): the rest of the chunk skipped");
        return;
      }
    }
  }

  void on_record(std::uint8_t opcode, Cursor& body, std::uint64_t at, const MessageCallback& on_message) {
    switch (opcode) {
      case kHeader:
        header.profile = body.string("profile");
        header.library = body.string("library");
        break;
      case kSchema: {
        auto s = detail::decode_schema(body);
        schemas[s.id] = std::move(s);
        break;
      }
      case kChannel: {
        auto ch = detail::decode_channel(body);
        channels[ch.id] = std::move(ch);
        break;
      }
      case kMetadata:
        if (!summary) metadata.push_back(detail::decode_metadata(body));
        break;
      case kMessage: {
        MessageView m;
        m.channel_id = body.get<std::uint16_t>("channel_id");
        m.sequence = body.get<std::uint32_t>("sequence");
        m.log_time = body.get<std::uint64_t>("log_time");
        m.publish_time = body.get<std::uint64_t>("publish_time");
        m.size = body.left();
        m.data = body.take(m.size, "data");
        const auto channel = channels.find(m.channel_id);
        if (channel == channels.end()) {
          problem(at, "message on channel " + std::to_string(m.channel_id) + ", which no channel record defines: skipped");
          break;
        }
        if (!summary) {
          if (scanned.message_count == 0 || m.log_time < scanned.message_start_time) scanned.message_start_time = m.log_time;
          scanned.message_end_time = std::max(scanned.message_end_time, m.log_time);
          ++scanned.message_count;
          ++scanned.channel_message_counts[m.channel_id];
        }
        if (on_message) on_message(channel->second, m);
        break;
      }
      default: break;  // indexes, attachments, unknown opcodes: skipped as the specification says
    }
  }

  void read_chunk(Cursor& body, std::uint64_t at, const MessageCallback& on_message) {
    body.get<std::uint64_t>("message_start_time");
    body.get<std::uint64_t>("message_end_time");
    const auto uncompressed_size = body.get<std::uint64_t>("uncompressed_size");
    const auto crc = body.get<std::uint32_t>("uncompressed_crc");
    const auto compression = body.string("compression");
    const auto n = body.get<std::uint64_t>("records length");
    const auto* records = body.take(n, "records");
    const std::string error = detail::decompress(compression, records, n, uncompressed_size, chunk);
    if (!error.empty()) {
      problem(at, error + ": chunk skipped");
      return;
    }
    if (crc != 0) {
      const std::uint32_t computed = detail::crc32(0, chunk.data(), chunk.size());
      if (computed != crc) {
        problem(at, "chunk CRC mismatch (stored " + std::to_string(crc) + ", computed " + std::to_string(computed) +
                        "): chunk skipped");
        return;
      }
    }
    if (!summary) ++scanned.chunk_count;
    scan_chunk(at, on_message);
  }

  Statistics scanned;
};

Reader::Reader(const std::string& path) : s_(std::make_unique<State>()) {
  s_->path = path;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error("cannot open '" + path + "': " + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw Error("'" + path + "' is not a regular file");
  }
  s_->size = static_cast<std::size_t>(st.st_size);
  if (s_->size < sizeof kMagic || s_->size == 0) {
    ::close(fd);
    throw Error("'" + path + "' is not an MCAP file: " + std::to_string(s_->size) + " bytes, shorter than the magic");
  }
  void* p = ::mmap(nullptr, s_->size, PROT_READ, MAP_PRIVATE, fd, 0);
  ::close(fd);
  if (p == MAP_FAILED) throw Error("cannot map '" + path + "': " + std::strerror(errno));
  s_->data = static_cast<const std::uint8_t*>(p);
  if (std::memcmp(s_->data, kMagic, sizeof kMagic) != 0) {
    ::munmap(p, s_->size);
    throw Error("'" + path + "' is not an MCAP file (byte 0: no MCAP magic)");
  }
  s_->summary = s_->read_summary();
  s_->summary_problems = s_->problems;
  if (!s_->summary) {
    s_->schemas.clear();
    s_->channels.clear();
    s_->metadata.clear();
  }
  s_->readable = s_->size;
}

Reader::~Reader() { ::munmap(const_cast<std::uint8_t*>(s_->data), s_->size); }

void Reader::scan(const MessageCallback& on_message) {
  auto& s = *s_;
  s.problems = s.summary_problems;  // what opening found stays; the last scan's own are replaced
  s.scanned = Statistics{};
  if (!s.summary) s.metadata.clear();
  std::size_t at = sizeof kMagic;
  bool ended = false;
  while (at < s.size && !ended) {
    const std::size_t left = s.size - at;
    if (left < kRecordHeader) {
      s.problem(at, "file truncated: " + std::to_string(left) + " byte(s) of a record header");
      break;
    }
    Cursor head(s.data + at, kRecordHeader);
    const auto opcode = head.get<std::uint8_t>("opcode");
    const auto length = head.get<std::uint64_t>("length");
    if (length > left - kRecordHeader) {
      s.problem(at, "file truncated: " + detail::opcode_name(opcode) + " record of " + std::to_string(length) +
                        " bytes, only " + std::to_string(left - kRecordHeader) + " left");
      break;
    }
    Cursor body(s.data + at + kRecordHeader, length);
    try {
      if (opcode == kChunk) {
        s.read_chunk(body, at, on_message);
      } else if (opcode == kDataEnd || opcode == kFooter) {
        ended = true;
      } else {
        s.on_record(opcode, body, at, on_message);
      }
    } catch (const ShortRead& e) {
      s.problem(at, detail::opcode_name(opcode) + " record: field '" + e.field + "' runs past its " +
                        std::to_string(length) + " bytes: record skipped");
    }
    at += kRecordHeader + length;
  }
  s.readable = ended ? s.size : at;
}

bool Reader::has_summary() const { return s_->summary; }
const Statistics& Reader::statistics() const { return s_->summary ? s_->stats : s_->scanned; }
const std::map<std::uint16_t, Schema>& Reader::schemas() const { return s_->schemas; }
const std::map<std::uint16_t, Channel>& Reader::channels() const { return s_->channels; }
const std::vector<Metadata>& Reader::metadata() const { return s_->metadata; }
const Header& Reader::header() const { return s_->header; }
std::uint64_t Reader::file_size() const { return s_->size; }
const std::string& Reader::path() const { return s_->path; }
const std::vector<std::string>& Reader::problems() const { return s_->problems; }
std::uint64_t Reader::readable_bytes() const { return s_->readable; }

}  // namespace plumb::mcap
