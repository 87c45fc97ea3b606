// A small recording written by plumb::mcap::Writer, and what a scan reads back from a file.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "plumb/mcap/reader.hpp"
#include "plumb/mcap/writer.hpp"

namespace plumb::mcap::test {

// In memory where the machine has it: the cut-at-every-offset test writes thousands of files.
inline std::string temp_path(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
  return (dir / ("plumb_mcap_" + std::to_string(::getpid()) + "_" + name)).string();
}

struct Read {
  std::uint64_t payload;  // first 8 bytes of the message, the value written
  std::string topic;
  std::uint64_t log_time;
};

// `messages` messages alternating between two channels, payload i, log_time 1000 + i; small
// chunks (`chunk_size`) so that a file has many.
inline void write_sample(const std::string& path, int messages, std::size_t chunk_size = 512, bool compress = true) {
  WriterOptions options;
  options.chunk_size = chunk_size;
  options.compress = compress;
  Writer w(path, options);
  const auto schema = w.add_schema("plumb::msg::Test", "omgidl", "module plumb { module msg { struct Test { unsigned long long v; }; }; };");
  const std::uint16_t channels[2] = {w.add_channel(schema, "plumb/a", "cdr", {{"qos", "reliable"}}),
                                     w.add_channel(schema, "plumb/b", "cdr")};
  w.write_metadata({"plumb", {{"host", "test"}, {"vendor", "none"}}});
  for (int i = 0; i < messages; ++i) {
    std::uint8_t data[8];
    for (int b = 0; b < 8; ++b) data[b] = static_cast<std::uint8_t>(static_cast<std::uint64_t>(i) >> (8 * b));
    MessageView m;
    m.channel_id = channels[i % 2];
    m.sequence = static_cast<std::uint32_t>(i);
    m.log_time = 1000 + static_cast<std::uint64_t>(i);
    m.publish_time = static_cast<std::uint64_t>(i);
    m.data = data;
    m.size = sizeof data;
    w.write(m);
  }
  w.close();
}

inline std::vector<Read> read_all(Reader& r) {
  std::vector<Read> out;
  r.scan([&](const Channel& c, const MessageView& m) {
    std::uint64_t v = 0;
    for (std::size_t b = 0; b < 8 && b < m.size; ++b) v |= static_cast<std::uint64_t>(m.data[b]) << (8 * b);
    out.push_back({v, c.topic, m.log_time});
  });
  return out;
}

inline std::vector<char> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

inline void write_bytes(const std::string& path, const std::vector<char>& bytes, std::size_t n) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(n));
}

}  // namespace plumb::mcap::test
