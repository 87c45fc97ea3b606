// Writes an MCAP file to the specification (https://mcap.dev/spec): header, schemas and channels
// as they are added, messages in zstd chunks with their message indexes, metadata, then at close
// the summary (schemas, channels, statistics, chunk and metadata indexes, summary offsets) and
// the footer. Each chunk goes to the kernel as soon as it is closed, so a killed writer leaves
// every closed chunk readable (Reader recovers a file without summary).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "plumb/mcap/records.hpp"

namespace plumb::mcap {

struct WriterOptions {
  std::string profile;                 // "" : not one of the well-known profiles (ros1, ros2)
  std::string library = "plumb";       // the writer's name and version, for debugging
  std::size_t chunk_size = 1 << 20;    // a chunk closes when its records reach this many bytes
  bool compress = true;                // zstd; false stores chunks uncompressed
  int zstd_level = 1;                  // the fastest level: recording must keep up with 10 kHz
};

class Writer {
 public:
  // Creates (truncates) `path`; Error if it cannot.
  Writer(const std::string& path, const WriterOptions& options = {});
  ~Writer();  // closes if close() was not called; errors are then lost: call close()
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  // Ids are given out in order from 1. A schema and a channel are written at once, ahead of the
  // chunks that use them.
  std::uint16_t add_schema(const std::string& name, const std::string& encoding, const std::string& data);
  std::uint16_t add_channel(std::uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                            const std::map<std::string, std::string>& metadata = {});
  // Appends to the open chunk; the chunk is written when it reaches options.chunk_size.
  void write(const MessageView& message);
  void write_metadata(const Metadata& metadata);
  // Writes the open chunk now (a recorder calls this once a second: a kill loses at most that).
  void flush();
  // Last chunk, data end, summary, footer. After an Error from any call (disk full), close() cuts
  // the file back to the last whole chunk and still tries to finish it; if that fails too the
  // file ends after its last whole chunk, which Reader recovers.
  void close();

  const Statistics& statistics() const;
  std::uint64_t bytes_written() const;  // file size so far
  const std::string& path() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace plumb::mcap
