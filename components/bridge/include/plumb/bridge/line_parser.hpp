// Incremental parser of the ASCII line mode of docs/protocol.md: sensor CSV lines (shared
// docs/conventions.md) arriving in byte chunks of any size. A header line may come at any time (the
// board restarted) and replaces the previous one. Bad lines are counted (csv_errors) with an
// error naming the line and column, and parsing goes on with the next line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "plumb/bridge/counters.hpp"
#include "plumb/csv/files.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::bridge {

class LineParser {
 public:
  // Lines longer than this (no newline in sight: binary noise) are dropped and counted.
  static constexpr std::size_t kMaxLineLength = 1024;

  LineParser(Counters& counters, std::string source_name = "serial");
  ~LineParser();

  void feed(std::span<const std::uint8_t> bytes, std::vector<Sample>& out);
  // End of stream: an unterminated last line is parsed; the header is forgotten.
  void finish(std::vector<Sample>& out);

  bool has_header() const { return reader_ != nullptr; }
  // The last bad line's error ("serial:12: column 'fy': bad number 'x'"), empty if none.
  const std::string& last_error() const { return last_error_; }

 private:
  void parse_line(const std::string& line, std::vector<Sample>& out);
  void error(const std::string& message);
  std::string without_location(const std::string& what) const;

  Counters& c_;
  std::string source_;
  std::string line_;
  bool overlong_ = false;
  std::size_t line_number_ = 0;
  std::istringstream row_;
  std::unique_ptr<csv::SensorReader> reader_;
  std::string last_error_;
};

// True when `line` is a sensor CSV header rather than a data row (its first field is a name).
bool looks_like_header(const std::string& line);

}  // namespace plumb::bridge
