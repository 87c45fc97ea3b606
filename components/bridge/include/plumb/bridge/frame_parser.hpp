// Incremental parser of the binary frames of docs/protocol.md: feed it byte chunks of any size,
// get samples out. It resynchronises on the sync word after garbage and never loses a valid frame
// that starts inside garbage or inside a corrupted frame (after a CRC failure it moves on by one
// byte, not by a frame). Every byte it cannot use is counted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "plumb/bridge/counters.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::bridge {

class FrameParser {
 public:
  // Counts into `counters` (frames_ok, crc_errors, truncated, bad_version, resyncs, bytes_skipped).
  explicit FrameParser(Counters& counters) : c_(counters) {}

  // Appends the samples of every complete valid frame in the stream so far to `out`.
  void feed(std::span<const std::uint8_t> bytes, std::vector<Sample>& out);
  // End of stream (device closed, file ended): a partial frame left over counts as truncated,
  // other leftover bytes as skipped. The parser is then ready for a new stream.
  void finish();

  std::size_t pending_bytes() const { return buf_.size() - pos_; }

 private:
  enum class Step { NeedMore, Advanced };
  Step step(std::vector<Sample>& out);
  void skip(std::size_t n);
  void end_skip_run();
  void note_corrupt_frame(std::uint64_t end);
  void resolve_corrupt_frame(bool header_inside);
  bool plausible_v1_header(std::size_t at) const;

  Counters& c_;
  std::vector<std::uint8_t> buf_;
  std::size_t pos_ = 0;          // first unparsed byte in buf_
  std::uint64_t consumed_ = 0;   // stream offset of buf_[0]
  bool in_skip_run_ = false;
  // A v1 frame whose CRC failed, not yet classified: truncated if another plausible frame header
  // starts before its end, a CRC error otherwise.
  bool corrupt_pending_ = false;
  std::uint64_t corrupt_end_ = 0;  // stream offset
};

}  // namespace plumb::bridge
