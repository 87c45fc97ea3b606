// WITS level 0, the rig's ASCII feed: a frame is a line "&&", then one item per line (four digits
// RRII, record and item, followed at once by the value: "01081234.56"), then a line "!!". Lines
// end in CR LF (CR or LF alone are taken too). The parser takes bytes as they come, in pieces of
// any size, gives every complete frame, and counts what it could not use; it never throws on
// input and its memory is bounded whatever it is fed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace plumb::wits {

struct Item {
  int code = 0;       // RRII as a number: 108 for record 01, item 08
  std::string value;  // as sent, blanks around it removed
};

struct Frame {
  std::vector<Item> items;
};

struct ParserCounters {
  std::uint64_t frames = 0;          // complete frames ("&&" ... "!!")
  std::uint64_t items = 0;           // item lines in complete frames
  std::uint64_t garbage_bytes = 0;   // bytes outside frames, and of lines that are not items
  std::uint64_t garbage_runs = 0;    // runs of such bytes (one burst of noise counts once)
  std::uint64_t bad_lines = 0;       // lines inside a frame that are not "RRIIvalue"
  std::uint64_t cut_frames = 0;      // frames that never ended: a new "&&", the stream's end, too long
  std::uint64_t empty_frames = 0;    // "&&" then "!!" with no item between
};

class FrameParser {
 public:
  // The longest line kept (WITS lines are a dozen characters); longer lines are garbage.
  static constexpr std::size_t kMaxLine = 128;
  // More items than this in one frame: the frame is cut (its "!!" was lost in noise).
  static constexpr std::size_t kMaxItems = 512;

  // Appends every frame that `data` completes to `out`, oldest first.
  void feed(const std::uint8_t* data, std::size_t size, std::vector<Frame>& out);
  void feed(const std::string& text, std::vector<Frame>& out);
  // The stream ended (a connection closed, a device vanished): a frame in progress is cut, a line in
  // progress dropped; the next bytes start afresh.
  void end_of_stream();

  const ParserCounters& counters() const { return c_; }

 private:
  void take_line(std::vector<Frame>& out);
  void garbage(std::size_t bytes);
  void cut_frame();

  ParserCounters c_;
  std::string line_;
  std::size_t line_bytes_ = 0;  // bytes of the current line, kept or not (terminator excluded)
  bool line_bad_ = false;       // a byte no WITS line holds, or too long
  bool in_frame_ = false;
  bool last_was_garbage_ = false;
  Frame frame_;
};

// "0108" -> 108; -1 unless exactly four digits.
int parse_item_code(const std::string& text);
// The value as a number: finite, the whole text; false otherwise.
bool parse_value(const std::string& text, double& value);

}  // namespace plumb::wits
