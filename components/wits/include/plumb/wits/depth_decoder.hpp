// From WITS frames to the depth of a tool: which items carry what, in which unit, and the flags
// the rig's depth reports carry (moving, in slips), taken from items the rig sends or derived from
// the depth itself. No DDS here.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

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
  double moving_tolerance_m = 0.01;  // derived: a bit depth change beyond this since the last frame is motion
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

  DepthOptions o_;
  DecoderCounters c_;
  double last_bit_m_ = std::numeric_limits<double>::quiet_NaN();
  double still_since_s_ = std::numeric_limits<double>::quiet_NaN();
};

// "0108" or "108" -> 108; throws std::invalid_argument naming `what` otherwise.
int item_code_option(const std::string& text, const std::string& what);

}  // namespace plumb::wits
