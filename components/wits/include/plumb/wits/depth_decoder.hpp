// From WITS frames to the depth of a tool: which items carry what, in which unit, and the flags
// the rig's depth reports carry (moving, in slips), taken from items the rig sends or derived from
// the depth itself. No DDS here.
#pragma once

#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "plumb/wits/frame_parser.hpp"

namespace plumb::wits {

inline constexpr double kFootInMetres = 0.3048;

struct DepthOptions {
  int bit_item = 108;     // record 01 item 08: bit depth, measured
  int hole_item = 110;    // record 01 item 10: hole depth, measured
  int moving_item = -1;   // an item whose non-zero value says the string moves (-1: from the depth)
  int slips_item = -1;    // an item whose non-zero value says the string is in slips (-1: from the depth)
  double unit_m = 1.0;    // metres per unit of the feed's depths (kFootInMetres for a feed in feet)
  double sensor_offset_m = 0;        // how far the sensor sits behind (above) the bit
  double moving_tolerance_m = 0.01;  // derived: a bit depth change beyond this is motion, since the last
                                     // frame or over the last moving_window_s (slow drilling: 30 m/h
                                     // is 8 mm between two frames a second apart)
  double moving_window_s = 5;
  // A depth a rig cannot report is refused and counted, never published: a bit depth outside
  // [min_depth_m, max_depth_m] (the deepest wells are 12-15 km), or one that moved faster than
  // max_speed_mps from the last depth accepted (a rig's blocks travel at most 1-2 m/s; over the
  // time between their arrivals, at least one second: frames delivered together). A new
  // level that holds (jump_confirm_frames frames in a row within that speed of each other) is a
  // feed that was reset or a depth corrected at the rig: it is taken from then on.
  double min_depth_m = -1;
  double max_depth_m = 15000;
  double max_speed_mps = 5;
  int jump_confirm_frames = 3;
  double slips_still_s = 10;         // derived: still this long with the bit off bottom is in slips (0: never)
  double off_bottom_m = 0.5;         // derived: the bit this far above the hole depth is off bottom
};

// One frame's depth for the tool.
struct DepthReading {
  double depth_m = std::numeric_limits<double>::quiet_NaN();       // the sensor's: bit depth - offset
  double bit_depth_m = std::numeric_limits<double>::quiet_NaN();
  double hole_depth_m = std::numeric_limits<double>::quiet_NaN();  // NaN: not sent
  bool moving = false;
  bool in_slips = false;
};

struct DecoderCounters {
  std::uint64_t depths = 0;             // frames that gave a depth
  std::uint64_t frames_without_depth = 0;  // frames without a usable bit depth item
  std::uint64_t bad_values = 0;         // items read (depths, flags) whose value is not a number
  std::uint64_t out_of_range = 0;       // bit depths outside [min_depth_m, max_depth_m] or not finite
  std::uint64_t jumps = 0;              // bit depths that moved faster than max_speed_mps
};

class DepthDecoder {
 public:
  explicit DepthDecoder(DepthOptions options) : o_(options) {}
  // The frame's reading at `t_s` (seconds on any steady clock), or nothing when it carries no usable
  // bit depth (counted). Flag items not sent leave the flag to the derivation.
  std::optional<DepthReading> decode(const Frame& frame, double t_s);
  const DecoderCounters& counters() const { return c_; }

 private:
  std::optional<double> number(const Frame& frame, int code);

  bool plausible(double bit_m, double t_s);
  bool moving_by_trend(double bit_m, double t_s);

  DepthOptions o_;
  DecoderCounters c_;
  double last_bit_m_ = std::numeric_limits<double>::quiet_NaN();
  double last_t_s_ = std::numeric_limits<double>::quiet_NaN();
  double still_since_s_ = std::numeric_limits<double>::quiet_NaN();
  // The frames refused as a jump in a row (the candidate new level's last depth and time).
  int jumped_ = 0;
  double jump_bit_m_ = 0, jump_t_s_ = 0;
  std::deque<std::pair<double, double>> recent_;  // (t_s, bit_m) over the last moving_window_s
};

// "0108" or "108" -> 108; throws std::invalid_argument naming `what` otherwise.
int item_code_option(const std::string& text, const std::string& what);

}  // namespace plumb::wits
