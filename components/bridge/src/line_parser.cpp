#include "plumb/bridge/line_parser.hpp"

#include <cctype>

namespace plumb::bridge {

bool looks_like_header(const std::string& line) {
  const auto first = line.find_first_not_of(" \t");
  return first != std::string::npos && std::isalpha(static_cast<unsigned char>(line[first])) &&
         line.compare(first, 3, "nan") != 0 && line.compare(first, 3, "inf") != 0;
}

LineParser::LineParser(Counters& counters, std::string source_name) : c_(counters), source_(std::move(source_name)) {}
LineParser::~LineParser() = default;

// The reader numbers its own lines; ours count the whole stream, so its "source:line: " goes.
std::string LineParser::without_location(const std::string& what) const {
  const auto cut = what.find(": ", source_.size() + 1);
  return cut == std::string::npos ? what : what.substr(cut + 2);
}

void LineParser::error(const std::string& message) {
  ++c_.csv_errors;
  last_error_ = message;
}

void LineParser::feed(std::span<const std::uint8_t> bytes, std::vector<Sample>& out) {
  for (const std::uint8_t byte : bytes) {
    if (byte == '\n') {
      ++line_number_;
      if (overlong_) {
        overlong_ = false;
      } else {
        parse_line(line_, out);
      }
      line_.clear();
      continue;
    }
    if (overlong_) {
      ++c_.bytes_skipped;
      continue;
    }
    line_.push_back(static_cast<char>(byte));
    if (line_.size() > kMaxLineLength) {
      error(source_ + ":" + std::to_string(line_number_ + 1) + ": line longer than " +
            std::to_string(kMaxLineLength) + " bytes, dropped");
      c_.bytes_skipped += line_.size();
      line_.clear();
      overlong_ = true;
    }
  }
}

void LineParser::finish(std::vector<Sample>& out) {
  if (!line_.empty() && !overlong_) {
    ++line_number_;
    parse_line(line_, out);
  }
  line_.clear();
  overlong_ = false;
  reader_.reset();
}

void LineParser::parse_line(const std::string& line, std::vector<Sample>& out) {
  const auto first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos || line[first] == '#') return;
  const std::string where = source_ + ":" + std::to_string(line_number_) + ": ";
  if (looks_like_header(line)) {
    row_.clear();
    row_.str(line + "\n");
    try {
      reader_ = std::make_unique<csv::SensorReader>(row_, source_);
    } catch (const csv::Error& e) {
      reader_.reset();
      c_.bytes_skipped += line.size() + 1;
      error(where + without_location(e.what()));
    }
    return;
  }
  if (!reader_) {
    c_.bytes_skipped += line.size() + 1;
    error(where + "data line before any header line, dropped");
    return;
  }
  row_.clear();
  row_.str(line + "\n");
  try {
    Sample s;
    if (reader_->next(s)) {
      ++c_.lines_ok;
      out.push_back(s);
    }
  } catch (const csv::Error& e) {
    c_.bytes_skipped += line.size() + 1;
    error(where + without_location(e.what()));
  }
}

}  // namespace plumb::bridge
