// A rig's WITS level-0 record 01 frame as a rig sends it: date, time, bit depth, hole depth. Written
// by whatever plays a rig (plumb-wits-send, plumb-sim --wits); read back by frame_parser and
// depth_decoder.
#pragma once

#include <ctime>
#include <string>

namespace plumb::wits {

// Depths in metres, written in the feed's unit (unit_m metres per unit, 2 decimals); the date and
// time items (0105, 0106) are the UTC of `now`.
std::string record01_frame(double bit_depth_m, double hole_depth_m, double unit_m, std::time_t now);

}  // namespace plumb::wits
