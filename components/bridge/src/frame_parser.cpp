#include "plumb/bridge/frame_parser.hpp"

#include <cstring>

#include "little_endian.hpp"
#include "plumb/bridge/protocol.hpp"

namespace plumb::bridge {

void FrameParser::feed(std::span<const std::uint8_t> bytes, std::vector<Sample>& out) {
  // Compact before growing so the buffer stays about one chunk plus one frame long.
  if (pos_ > 0 && pos_ >= buf_.size() / 2) {
    buf_.erase(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(pos_));
    consumed_ += pos_;
    pos_ = 0;
  }
  buf_.insert(buf_.end(), bytes.begin(), bytes.end());
  while (step(out) == Step::Advanced) {
  }
}

bool FrameParser::plausible_v1_header(std::size_t at) const {
  const std::uint8_t* p = buf_.data() + at;
  return p[0] == kSync0 && p[1] == kSync1 && p[2] == kProtocolVersion && get_u16(p + 4) == kPayloadSizeV1;
}

void FrameParser::skip(std::size_t n) {
  pos_ += n;
  c_.bytes_skipped += n;
  in_skip_run_ = true;
  if (corrupt_pending_ && consumed_ + pos_ >= corrupt_end_) resolve_corrupt_frame(false);
}

void FrameParser::end_skip_run() {
  if (in_skip_run_) ++c_.resyncs;
  in_skip_run_ = false;
}

void FrameParser::note_corrupt_frame(std::uint64_t end) {
  // While one is pending the parser is still inside it (skip() resolves it once past its end):
  // a frame header here means that frame was cut short.
  if (corrupt_pending_) resolve_corrupt_frame(true);
  corrupt_pending_ = true;
  corrupt_end_ = end;
}

void FrameParser::resolve_corrupt_frame(bool header_inside) {
  if (header_inside) {
    ++c_.truncated;
  } else {
    ++c_.crc_errors;
  }
  corrupt_pending_ = false;
}

FrameParser::Step FrameParser::step(std::vector<Sample>& out) {
  const std::size_t avail = buf_.size() - pos_;
  if (avail == 0) return Step::NeedMore;
  const std::uint8_t* p = buf_.data() + pos_;
  if (p[0] != kSync0 || (avail >= 2 && p[1] != kSync1)) {
    // Skip to the next possible sync word start.
    const void* next = avail > 1 ? std::memchr(p + 1, kSync0, avail - 1) : nullptr;
    skip(next ? static_cast<std::size_t>(static_cast<const std::uint8_t*>(next) - p) : avail);
    return Step::Advanced;
  }
  if (avail < kHeaderSize) return Step::NeedMore;
  const std::uint8_t version = p[2];
  const std::size_t length = get_u16(p + 4);
  if (length > kMaxPayloadSize || (version == kProtocolVersion && length != kPayloadSizeV1)) {
    skip(1);
    return Step::Advanced;
  }
  const std::size_t frame_size = kHeaderSize + length + kCrcSize;
  if (avail < frame_size) return Step::NeedMore;
  const std::uint64_t start = consumed_ + pos_;
  if (crc32(p, kHeaderSize + length) != get_u32(p + kHeaderSize + length)) {
    // Move on by one byte only: a valid frame may start inside this one.
    if (version == kProtocolVersion) note_corrupt_frame(start + frame_size);
    skip(1);
    return Step::Advanced;
  }
  if (corrupt_pending_) resolve_corrupt_frame(true);  // a frame inside it: it was cut short
  end_skip_run();
  if (version != kProtocolVersion) {
    ++c_.bad_version;
  } else {
    ++c_.frames_ok;
    out.push_back(decode_payload_v1(p + kHeaderSize));
  }
  pos_ += frame_size;
  return Step::Advanced;
}

void FrameParser::finish() {
  const std::size_t avail = buf_.size() - pos_;
  if (avail > 0) {
    const std::uint8_t* p = buf_.data() + pos_;
    const bool starts_frame =
        avail >= 2 && p[0] == kSync0 && p[1] == kSync1 && (avail < kHeaderSize || plausible_v1_header(pos_));
    if (corrupt_pending_) resolve_corrupt_frame(starts_frame);
    if (starts_frame) ++c_.truncated;
    c_.bytes_skipped += avail;
    in_skip_run_ = true;
  }
  if (corrupt_pending_) resolve_corrupt_frame(false);
  end_skip_run();
  buf_.clear();
  pos_ = 0;
  consumed_ = 0;
}

}  // namespace plumb::bridge
