// Fuzzes the binary frame parser, the mode-detecting stream parser and the sample checks.
// Beyond "no crash, no leak, no UB": the same bytes must give the same samples and counters
// however they are chunked (the first input byte picks the chunk size).
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "plumb/bridge/frame_parser.hpp"
#include "plumb/bridge/sample_checker.hpp"
#include "plumb/bridge/stream_parser.hpp"

namespace {

struct Result {
  plumb::bridge::Counters counters;
  std::vector<plumb::Sample> samples;
};

Result parse(std::span<const std::uint8_t> bytes, std::size_t chunk) {
  Result r;
  plumb::bridge::FrameParser parser(r.counters);
  for (std::size_t at = 0; at < bytes.size(); at += chunk)
    parser.feed(bytes.subspan(at, std::min(chunk, bytes.size() - at)), r.samples);
  parser.finish();
  return r;
}

bool same(const Result& a, const Result& b) {
  if (a.samples.size() != b.samples.size()) return false;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    if (a.samples[i].seq != b.samples[i].seq || a.samples[i].flags != b.samples[i].flags) return false;
    if (std::memcmp(a.samples[i].f.data(), b.samples[i].f.data(), sizeof(double) * 3) != 0) return false;
  }
  return a.counters.named() == b.counters.named();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t chunk = 1 + data[0] % 97;
  const std::span<const std::uint8_t> bytes(data + 1, size - 1);

  const Result whole = parse(bytes, bytes.size() + 1);
  const Result chunked = parse(bytes, chunk);
  if (!same(whole, chunked)) __builtin_trap();
  // Every byte is either in a valid frame or counted (bad-version frames aside).
  if (whole.counters.bad_version == 0 &&
      whole.counters.frames_ok * 70 + whole.counters.bytes_skipped != bytes.size())
    __builtin_trap();

  plumb::bridge::Counters counters;
  plumb::bridge::StreamParser stream(counters, plumb::bridge::Mode::Auto, "fuzz");
  plumb::bridge::SampleChecker checker(counters);
  std::vector<plumb::Sample> out;
  for (std::size_t at = 0; at < bytes.size(); at += chunk)
    stream.feed(bytes.subspan(at, std::min(chunk, bytes.size() - at)), out);
  stream.finish(out);
  for (auto& s : out) checker.check(s);
  return 0;
}
