#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench.hpp"
#include "plumb/bridge/frame_parser.hpp"
#include "plumb/bridge/line_parser.hpp"
#include "plumb/bridge/protocol.hpp"
#include "plumb/bridge/sample_checker.hpp"

namespace plumb::bench {
namespace {

using bridge::append_frame;
using bridge::encode_frame;
using bridge::kFrameSizeV1;
using Clock = std::chrono::steady_clock;
using Bytes = std::vector<std::uint8_t>;

Sample sample(std::uint64_t seq) {
  Sample s;
  s.seq = seq;
  s.t = static_cast<double>(seq) * 1e-3;
  s.f = {0.1 * static_cast<double>(seq % 7), -0.2, -9.81};
  s.b = {20.0, 1.0 + static_cast<double>(seq % 5), 40.0};
  s.w = {0.0, 0.0, 6.28};
  s.temp_c = 30.0;
  s.flags = flags::kHasGyro | flags::kHasTemperature;
  return s;
}

// Best of `repeats` runs of `work`, in seconds.
template <class F> double best_of(int repeats, F&& work) {
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    work();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return best;
}

volatile std::uint64_t g_sink;  // keeps the optimiser from dropping the measured work

void row(const char* name, double seconds, std::size_t bytes, std::size_t frames, double baseline_s) {
  std::printf("| %-38s | %9.1f | %12.3g | %8.2f |\n", name, static_cast<double>(bytes) / seconds / 1e6,
              static_cast<double>(frames) / seconds, seconds / baseline_s);
}

}  // namespace

void run_parser_throughput(std::size_t n, int repeats) {
  Bytes clean;
  clean.reserve(n * kFrameSizeV1);
  for (std::size_t i = 0; i < n; ++i) append_frame(clean, sample(i));
  // The same frames with 1% corrupted and noise bytes between some of them.
  Bytes damaged;
  for (std::size_t i = 0; i < n; ++i) {
    Bytes f = encode_frame(sample(i));
    if (i % 100 == 50) f[30] ^= 0x40;
    if (i % 100 == 75) damaged.insert(damaged.end(), {0x00, 0x13, 0xA5, 0x42, 0x99});
    damaged.insert(damaged.end(), f.begin(), f.end());
  }
  std::string ascii = bridge::ascii_header();
  const std::size_t n_ascii = n / 10;
  for (std::size_t i = 0; i < n_ascii; ++i) ascii += bridge::encode_ascii_line(sample(i));
  const std::size_t chunk = 4096;  // a serial read's worth

  Bytes copy(clean.size());
  const double t_memcpy = best_of(repeats, [&] {
    for (std::size_t at = 0; at < clean.size(); at += chunk)
      std::memcpy(copy.data() + at, clean.data() + at, std::min(chunk, clean.size() - at));
    g_sink = copy[copy.size() / 2];
  });
  const double t_crc = best_of(repeats, [&] {
    std::uint32_t x = 0;
    for (std::size_t i = 0; i < n; ++i) x ^= bridge::crc32(clean.data() + i * kFrameSizeV1, kFrameSizeV1 - 4);
    g_sink = x;
  });
  auto parse = [&](const Bytes& bytes, bool check) {
    bridge::Counters c;
    bridge::FrameParser parser(c);
    bridge::SampleChecker checker(c);
    std::vector<Sample> out;
    out.reserve(chunk / kFrameSizeV1 + 2);
    std::uint64_t got = 0;
    for (std::size_t at = 0; at < bytes.size(); at += chunk) {
      out.clear();
      parser.feed(std::span(bytes.data() + at, std::min(chunk, bytes.size() - at)), out);
      if (check)
        for (auto& s : out) checker.check(s);
      got += out.size();
    }
    parser.finish();
    g_sink = got;
  };
  const double t_parse = best_of(repeats, [&] { parse(clean, false); });
  const double t_parse_check = best_of(repeats, [&] { parse(clean, true); });
  const double t_damaged = best_of(repeats, [&] { parse(damaged, true); });
  const double t_ascii = best_of(repeats, [&] {
    bridge::Counters c;
    bridge::LineParser lines(c);
    std::vector<Sample> out;
    const auto* p = reinterpret_cast<const std::uint8_t*>(ascii.data());
    for (std::size_t at = 0; at < ascii.size(); at += chunk) {
      out.clear();
      lines.feed(std::span(p + at, std::min(chunk, ascii.size() - at)), out);
    }
    g_sink = c.lines_ok;
  });

  std::printf("\nParser throughput: %zu frames of %zu bytes (%.1f MB), fed in %zu-byte chunks, best of %d\n", n,
              kFrameSizeV1, static_cast<double>(clean.size()) / 1e6, chunk, repeats);
  std::printf("| %-38s | %9s | %12s | %8s |\n", "work over the same bytes", "MB/s", "frames/s", "x memcpy");
  std::printf("|%s|%s|%s|%s|\n", std::string(40, '-').c_str(), std::string(11, '-').c_str(),
              std::string(14, '-').c_str(), std::string(10, '-').c_str());
  row("memcpy (baseline)", t_memcpy, clean.size(), n, t_memcpy);
  row("CRC-32 of every frame only", t_crc, clean.size(), n, t_memcpy);
  row("frame parser", t_parse, clean.size(), n, t_memcpy);
  row("frame parser + sample checks", t_parse_check, clean.size(), n, t_memcpy);
  row("parser + checks, 1% damaged + noise", t_damaged, damaged.size(), n, t_memcpy);
  row("ASCII line parser (lines/s)", t_ascii, ascii.size(), n_ascii, t_memcpy * static_cast<double>(ascii.size()) /
                                                                           static_cast<double>(clean.size()));
  std::printf("frame parser / CRC-only time: %.2f (the CRC is the floor: every frame must be checked)\n",
              t_parse / t_crc);
  std::printf("1 kHz needs %.0f frames/s: the parser has %.0fx headroom on one core\n", 1000.0,
              static_cast<double>(n) / t_parse_check / 1000.0);
}

}  // namespace plumb::bench
