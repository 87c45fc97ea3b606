#include "plumb/wits/frame_parser.hpp"

#include <cmath>
#include <cstdlib>

namespace plumb::wits {
namespace {

bool is_terminator(std::uint8_t b) { return b == '\n' || b == '\r'; }
// What a WITS line may hold: printable ASCII and tabs.
bool is_text(std::uint8_t b) { return (b >= 0x20 && b < 0x7f) || b == '\t'; }

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

bool ends_with(const std::string& s, const char* tail) {
  const std::string t(tail);
  return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

}  // namespace

int parse_item_code(const std::string& text) {
  if (text.size() != 4) return -1;
  int code = 0;
  for (char ch : text) {
    if (ch < '0' || ch > '9') return -1;
    code = code * 10 + (ch - '0');
  }
  return code;
}

bool parse_value(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return false;
  value = v;
  return true;
}

void FrameParser::feed(const std::string& text, std::vector<Frame>& out) {
  feed(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), out);
}

void FrameParser::feed(const std::uint8_t* data, std::size_t size, std::vector<Frame>& out) {
  for (std::size_t i = 0; i < size; ++i) {
    const std::uint8_t b = data[i];
    if (is_terminator(b)) {
      take_line(out);
      continue;
    }
    ++line_bytes_;
    if (!is_text(b) || line_.size() >= kMaxLine) {
      line_bad_ = true;
      line_.clear();  // a bad line is never read: keep nothing of it (bounded memory)
    } else if (!line_bad_) {
      line_.push_back(static_cast<char>(b));
    }
  }
}

void FrameParser::garbage(std::size_t bytes) {
  if (bytes == 0) return;
  c_.garbage_bytes += bytes;
  if (!last_was_garbage_) ++c_.garbage_runs;
  last_was_garbage_ = true;
}

void FrameParser::cut_frame() {
  ++c_.cut_frames;
  in_frame_ = false;
  frame_.items.clear();
}

void FrameParser::take_line(std::vector<Frame>& out) {
  if (line_bytes_ == 0) return;  // the second byte of CR LF, or a blank line
  const bool bad = line_bad_;
  const std::size_t bytes = line_bytes_;
  const std::string text = trimmed(line_);
  line_.clear();
  line_bytes_ = 0;
  line_bad_ = false;
  if (bad) {
    if (in_frame_) ++c_.bad_lines;
    garbage(bytes);
    return;
  }
  if (text.empty()) return;
  // A frame starts at "&&", also at the end of a line of noise ("xq&&"): the noise is garbage.
  if (ends_with(text, "&&")) {
    if (in_frame_) cut_frame();
    garbage(text.size() - 2);
    in_frame_ = true;
    frame_.items.clear();
    last_was_garbage_ = false;
    return;
  }
  if (!in_frame_) {
    garbage(bytes);
    return;
  }
  if (text == "!!") {
    if (frame_.items.empty()) {
      ++c_.empty_frames;
    } else {
      ++c_.frames;
      c_.items += frame_.items.size();
      out.push_back(std::move(frame_));
    }
    frame_ = Frame{};
    in_frame_ = false;
    last_was_garbage_ = false;
    return;
  }
  const int code = text.size() > 4 ? parse_item_code(text.substr(0, 4)) : -1;
  if (code < 0) {
    ++c_.bad_lines;
    garbage(bytes);
    return;
  }
  frame_.items.push_back({code, trimmed(text.substr(4))});
  last_was_garbage_ = false;
  if (frame_.items.size() > kMaxItems) cut_frame();
}

void FrameParser::end_of_stream() {
  if (line_bytes_ > 0) {
    garbage(line_bytes_);
    if (in_frame_) ++c_.bad_lines;
  }
  line_.clear();
  line_bytes_ = 0;
  line_bad_ = false;
  if (in_frame_) cut_frame();
  last_was_garbage_ = false;
}

}  // namespace plumb::wits
