#include "plumb/wits/depth_decoder.hpp"

#include <stdexcept>

namespace plumb::wits {

int item_code_option(const std::string& text, const std::string& what) {
  const std::string padded = text.size() == 3 ? "0" + text : text;
  const int code = parse_item_code(padded);
  if (code < 100) throw std::invalid_argument(what + ": expected a WITS item code RRII (e.g. 0108), got '" + text + "'");
  return code;
}

std::optional<double> DepthDecoder::number(const Frame& frame, int code) {
  if (code < 0) return std::nullopt;
  // The last one counts when a frame repeats an item.
  std::optional<double> found;
  for (const auto& item : frame.items) {
    if (item.code != code) continue;
    double v = 0;
    if (parse_value(item.value, v)) {
      found = v;
    } else {
      ++c_.bad_values;
    }
  }
  return found;
}

std::optional<DepthReading> DepthDecoder::decode(const Frame& frame, double t_s) {
  const auto bit = number(frame, o_.bit_item);
  if (!bit) {
    ++c_.frames_without_depth;
    return std::nullopt;
  }
  DepthReading r;
  r.bit_depth_m = *bit * o_.unit_m;
  r.depth_m = r.bit_depth_m - o_.sensor_offset_m;
  if (const auto hole = number(frame, o_.hole_item)) r.hole_depth_m = *hole * o_.unit_m;

  const bool derived_moving = !std::isnan(last_bit_m_) && std::abs(r.bit_depth_m - last_bit_m_) > o_.moving_tolerance_m;
  const auto moving_item = number(frame, o_.moving_item);
  r.moving = moving_item ? *moving_item != 0 : derived_moving;
  last_bit_m_ = r.bit_depth_m;

  if (r.moving || std::isnan(still_since_s_)) still_since_s_ = t_s;
  const bool off_bottom = !std::isnan(r.hole_depth_m) && r.hole_depth_m - r.bit_depth_m > o_.off_bottom_m;
  const bool derived_slips = o_.slips_still_s > 0 && off_bottom && !r.moving && t_s - still_since_s_ >= o_.slips_still_s;
  const auto slips_item = number(frame, o_.slips_item);
  r.in_slips = slips_item ? *slips_item != 0 : derived_slips;
  ++c_.depths;
  return r;
}

}  // namespace plumb::wits
