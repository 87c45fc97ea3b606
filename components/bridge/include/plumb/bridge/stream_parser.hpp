// The byte stream of a sensor board in either mode of docs/protocol.md, chosen up front or
// detected from the data (auto: the first valid binary frame or the first CSV header decides).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "plumb/bridge/counters.hpp"
#include "plumb/bridge/frame_parser.hpp"
#include "plumb/bridge/line_parser.hpp"

namespace plumb::bridge {

enum class Mode { Auto, Binary, Ascii };
// "auto", "binary", "ascii"; nullopt otherwise.
std::optional<Mode> parse_mode(const std::string& name);
const char* mode_name(Mode mode);

class StreamParser {
 public:
  // Bytes kept while the mode is undecided; older ones are dropped and counted as skipped.
  static constexpr std::size_t kMaxDetectBytes = 64 * 1024;

  StreamParser(Counters& counters, Mode mode, std::string source_name = "serial");
  ~StreamParser();

  void feed(std::span<const std::uint8_t> bytes, std::vector<Sample>& out);
  // End of one stream (device closed); a detected mode is kept for the next one.
  void finish(std::vector<Sample>& out);

  Mode mode() const { return mode_; }  // Auto while undecided
  const std::string& last_line_error() const { return lines_.last_error(); }

 private:
  void detect(std::span<const std::uint8_t> bytes, std::vector<Sample>& out);
  void restart_probes();

  Counters& c_;
  Mode mode_;
  FrameParser frames_;
  LineParser lines_;
  Counters probe_counters_;
  std::unique_ptr<FrameParser> probe_frames_;
  std::unique_ptr<LineParser> probe_lines_;
  std::vector<std::uint8_t> undecided_;
  std::vector<Sample> probe_out_;
};

}  // namespace plumb::bridge
