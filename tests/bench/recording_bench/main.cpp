// plumb-bench-recording [BATCHES] [DIR]: samples/s and MB/s of recording full sensor batches
// (32 samples, as at 10 kHz) into MCAP, against writing the same CDR bytes with plain write()
// calls (no framing, no index, no compression): the ratio is what the format costs. Prints a table.
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "plumb/mcap/writer.hpp"
#include "plumb/topics/all.hpp"
#include "plumb/topics/cdr.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// Batches like a tool's: slowly varying signals with sensor noise, so compression sees real data.
std::vector<plumb::topics::SensorBatch> make_batches(std::size_t n) {
  std::mt19937_64 rng(1);
  std::normal_distribution<double> noise(0, 0.01);
  std::vector<plumb::topics::SensorBatch> out(n);
  std::uint64_t seq = 0;
  for (auto& b : out) {
    b.tool_id = "T1";
    b.samples.resize(32);
    for (auto& s : b.samples) {
      const double t = static_cast<double>(seq) * 1e-4;
      s.seq = seq++;
      s.stamp_ns = static_cast<std::int64_t>(seq) * 100000;
      s.fx = 0.3 * std::cos(6.28 * t) + noise(rng);
      s.fy = 0.3 * std::sin(6.28 * t) + noise(rng);
      s.fz = -9.8 + noise(rng);
      s.bx = 20 * std::cos(6.28 * t) + noise(rng);
      s.by = 20 * std::sin(6.28 * t) + noise(rng);
      s.bz = 40 + noise(rng);
      s.wx = noise(rng) * 1e-3;
      s.wy = noise(rng) * 1e-3;
      s.wz = 6.28 + noise(rng) * 1e-3;
      s.temp_c = 25;
      s.flags = 128 | 256;
    }
  }
  return out;
}

struct Result {
  double seconds;
  std::uint64_t bytes;
};

Result write_mcap(const std::vector<plumb::topics::SensorBatch>& batches, const std::string& path, bool compress) {
  const auto t0 = Clock::now();
  plumb::mcap::WriterOptions o;
  o.compress = compress;
  plumb::mcap::Writer w(path, o);
  const auto schema = w.add_schema("plumb::msg::SensorBatch", "omgidl", std::string(plumb::topics::idl_source<plumb::topics::SensorBatch>()));
  const auto channel = w.add_channel(schema, "plumb/sensor/raw", "cdr");
  std::vector<std::uint8_t> buffer;
  std::uint32_t seq = 0;
  for (const auto& b : batches) {
    plumb::topics::cdr::serialize(b, buffer);
    plumb::mcap::MessageView m;
    m.channel_id = channel;
    m.sequence = seq++;
    m.log_time = static_cast<std::uint64_t>(b.samples[0].stamp_ns);
    m.publish_time = m.log_time;
    m.data = buffer.data();
    m.size = buffer.size();
    w.write(m);
  }
  w.close();
  return {std::chrono::duration<double>(Clock::now() - t0).count(), w.bytes_written()};
}

// The baseline: the CDR bytes (already serialised, outside the timing) written as they are.
Result write_raw(const std::vector<std::vector<std::uint8_t>>& cdr, const std::string& path) {
  const auto t0 = Clock::now();
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::uint8_t> block;
  std::uint64_t total = 0;
  for (const auto& m : cdr) {
    block.insert(block.end(), m.begin(), m.end());
    if (block.size() >= (1u << 20)) {
      total += static_cast<std::uint64_t>(::write(fd, block.data(), block.size()));
      block.clear();
    }
  }
  total += static_cast<std::uint64_t>(::write(fd, block.data(), block.size()));
  ::close(fd);
  return {std::chrono::duration<double>(Clock::now() - t0).count(), total};
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::stoul(argv[1]) : 186000;  // 10 min at 10 kHz = 6e6 samples / 32
  const std::string dir = argc > 2 ? argv[2] : std::filesystem::temp_directory_path().string();
  const auto batches = make_batches(n);
  std::vector<std::vector<std::uint8_t>> cdr(n);
  for (std::size_t i = 0; i < n; ++i) plumb::topics::cdr::serialize(batches[i], cdr[i]);
  const double samples = static_cast<double>(n) * 32;
  const Result raw = write_raw(cdr, dir + "/plumb_bench_raw.bin");
  const Result zstd = write_mcap(batches, dir + "/plumb_bench_zstd.mcap", true);
  const Result plain = write_mcap(batches, dir + "/plumb_bench_plain.mcap", false);
  std::printf("%zu batches of 32 samples (%.0f samples, %.1f MB of CDR)\n\n", n, samples, static_cast<double>(raw.bytes) / 1e6);
  std::printf("| writer | samples/s | MB/s (CDR in) | file MB | time vs raw write |\n|---|---|---|---|---|\n");
  const auto row = [&](const char* name, const Result& r) {
    std::printf("| %s | %.3g | %.1f | %.1f | %.2f |\n", name, samples / r.seconds, static_cast<double>(raw.bytes) / 1e6 / r.seconds,
                static_cast<double>(r.bytes) / 1e6, r.seconds / raw.seconds);
  };
  row("raw write() of the CDR bytes (baseline)", raw);
  row("MCAP, zstd level 1 (plumb record)", zstd);
  row("MCAP, uncompressed (--uncompressed)", plain);
  std::printf("\nNeeded at 10 kHz: 1e4 samples/s, %.2f MB/s of CDR.\n", static_cast<double>(raw.bytes) / samples * 1e4 / 1e6);
  for (const char* f : {"/plumb_bench_raw.bin", "/plumb_bench_zstd.mcap", "/plumb_bench_plain.mcap"}) std::filesystem::remove(dir + f);
  return 0;
}
