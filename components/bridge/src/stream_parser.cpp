#include "plumb/bridge/stream_parser.hpp"

namespace plumb::bridge {

std::optional<Mode> parse_mode(const std::string& name) {
  if (name == "auto") return Mode::Auto;
  if (name == "binary") return Mode::Binary;
  if (name == "ascii") return Mode::Ascii;
  return std::nullopt;
}

const char* mode_name(Mode mode) {
  switch (mode) {
    case Mode::Binary: return "binary";
    case Mode::Ascii: return "ascii";
    case Mode::Auto: break;
  }
  return "auto";
}

StreamParser::StreamParser(Counters& counters, Mode mode, std::string source_name)
    : c_(counters), mode_(mode), frames_(counters), lines_(counters, std::move(source_name)) {
  if (mode_ == Mode::Auto) restart_probes();
}

StreamParser::~StreamParser() = default;

void StreamParser::restart_probes() {
  // The probes count into a scratch set, so nothing is counted twice once the mode is known.
  probe_counters_ = Counters{};
  probe_frames_ = std::make_unique<FrameParser>(probe_counters_);
  probe_lines_ = std::make_unique<LineParser>(probe_counters_);
}

void StreamParser::feed(std::span<const std::uint8_t> bytes, std::vector<Sample>& out) {
  switch (mode_) {
    case Mode::Binary: frames_.feed(bytes, out); break;
    case Mode::Ascii: lines_.feed(bytes, out); break;
    case Mode::Auto: detect(bytes, out); break;
  }
}

void StreamParser::detect(std::span<const std::uint8_t> bytes, std::vector<Sample>& out) {
  undecided_.insert(undecided_.end(), bytes.begin(), bytes.end());
  probe_out_.clear();
  probe_frames_->feed(bytes, probe_out_);
  probe_lines_->feed(bytes, probe_out_);
  if (probe_counters_.frames_ok > 0) {
    mode_ = Mode::Binary;
  } else if (probe_lines_->has_header()) {
    mode_ = Mode::Ascii;
  } else if (undecided_.size() > kMaxDetectBytes) {
    // Noise: keep only the tail, which may hold the start of the first frame or line.
    const std::size_t keep = 4096;
    const std::size_t dropped = undecided_.size() - keep;
    c_.bytes_skipped += dropped;
    ++c_.resyncs;
    undecided_.erase(undecided_.begin(), undecided_.begin() + static_cast<std::ptrdiff_t>(dropped));
    restart_probes();
    probe_frames_->feed(undecided_, probe_out_);
    probe_lines_->feed(undecided_, probe_out_);
    return;
  } else {
    return;
  }
  probe_frames_.reset();
  probe_lines_.reset();
  std::vector<std::uint8_t> replay;
  replay.swap(undecided_);
  feed(replay, out);
}

void StreamParser::finish(std::vector<Sample>& out) {
  switch (mode_) {
    case Mode::Binary: frames_.finish(); break;
    case Mode::Ascii: lines_.finish(out); break;
    case Mode::Auto:
      if (!undecided_.empty()) {
        c_.bytes_skipped += undecided_.size();
        ++c_.resyncs;
        undecided_.clear();
      }
      restart_probes();
      break;
  }
}

}  // namespace plumb::bridge
