// libFuzzer target: the WITS level-0 frame parser and depth decoder on arbitrary bytes, fed in
// pieces whose sizes come from the input too. Whatever came before, a line break and a good frame
// must give that frame's depth (at once, or once it has held for the frames the decoder needs to
// accept a new level after a jump); the counters never exceed the bytes fed.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "plumb/wits/depth_decoder.hpp"
#include "plumb/wits/frame_parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  plumb::wits::FrameParser parser;
  plumb::wits::DepthDecoder decoder({});
  std::vector<plumb::wits::Frame> frames;
  std::size_t at = 0;
  double t = 0;
  while (at < size) {
    const std::size_t piece = 1 + data[at] % 64;
    const std::size_t n = std::min(piece, size - at);
    parser.feed(data + at, n, frames);
    at += n;
    if (data[at - 1] == 0xfe) parser.end_of_stream();
  }
  for (const auto& f : frames) decoder.decode(f, t += 1);
  if (parser.counters().garbage_bytes > size) std::abort();
  frames.clear();
  // The line break may also end a frame left open by the input ("&&" ... "!!" without its CR LF):
  // the good frame is the last one out.
  parser.feed("\r\n&&\r\n01081234.50\r\n!!\r\n", frames);
  if (frames.empty() || frames.size() > 2) std::abort();
  const plumb::wits::DepthOptions defaults;
  std::optional<plumb::wits::DepthReading> reading;
  for (int k = 1; k <= defaults.jump_confirm_frames; ++k) {
    reading = decoder.decode(frames.back(), t + k);
    if (reading && reading->depth_m != 1234.5) std::abort();
  }
  if (!reading) std::abort();
  return 0;
}
