#include "plumb/wits/depth_decoder.hpp"

#include <algorithm>
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

bool DepthDecoder::plausible(double bit_m, double t_s) {
  if (!std::isfinite(bit_m) || bit_m < o_.min_depth_m || bit_m > o_.max_depth_m) {
    ++c_.out_of_range;
    return false;
  }
  const auto within_speed = [&](double from_m, double from_s) {
    // Time on arrival, at least a second: frames a network or a serial buffer delivers together
    // were sent apart (a rig sends about one a second).
    return std::abs(bit_m - from_m) <= o_.max_speed_mps * std::max(t_s - from_s, 1.0);
  };
  if (std::isnan(last_bit_m_) || within_speed(last_bit_m_, last_t_s_)) {
    jumped_ = 0;
    return true;
  }
  jumped_ = jumped_ > 0 && within_speed(jump_bit_m_, jump_t_s_) ? jumped_ + 1 : 1;
  jump_bit_m_ = bit_m, jump_t_s_ = t_s;
  if (jumped_ >= o_.jump_confirm_frames) {  // a new level that holds: the feed was reset
    jumped_ = 0;
    recent_.clear();
    return true;
  }
  ++c_.jumps;
  return false;
}

bool DepthDecoder::moving_by_trend(double bit_m, double t_s) {
  recent_.emplace_back(t_s, bit_m);
  while (recent_.size() > 1 && recent_.front().first < t_s - o_.moving_window_s) recent_.pop_front();
  const auto [lo, hi] = std::minmax_element(recent_.begin(), recent_.end(),
                                            [](const auto& a, const auto& b) { return a.second < b.second; });
  return hi->second - lo->second > o_.moving_tolerance_m;
}

std::optional<DepthReading> DepthDecoder::decode(const Frame& frame, double t_s) {
  const auto bit = number(frame, o_.bit_item);
  if (!bit) {
    ++c_.frames_without_depth;
    return std::nullopt;
  }
  DepthReading r;
  r.bit_depth_m = *bit * o_.unit_m;
  if (!plausible(r.bit_depth_m, t_s)) return std::nullopt;
  r.depth_m = r.bit_depth_m - o_.sensor_offset_m;
  if (const auto hole = number(frame, o_.hole_item)) r.hole_depth_m = *hole * o_.unit_m;

  // Motion from the depth: a step beyond the tolerance since the last frame (a connection's pull,
  // seen at once), or a trend beyond it over the window (slow drilling, steps under the tolerance).
  const bool stepped = !std::isnan(last_bit_m_) && std::abs(r.bit_depth_m - last_bit_m_) > o_.moving_tolerance_m;
  const bool derived_moving = moving_by_trend(r.bit_depth_m, t_s) || stepped;
  const auto moving_item = number(frame, o_.moving_item);
  r.moving = moving_item ? *moving_item != 0 : derived_moving;
  last_bit_m_ = r.bit_depth_m;
  last_t_s_ = t_s;

  if (r.moving || std::isnan(still_since_s_)) still_since_s_ = t_s;
  const bool off_bottom = !std::isnan(r.hole_depth_m) && r.hole_depth_m - r.bit_depth_m > o_.off_bottom_m;
  const bool derived_slips = o_.slips_still_s > 0 && off_bottom && !r.moving && t_s - still_since_s_ >= o_.slips_still_s;
  const auto slips_item = number(frame, o_.slips_item);
  r.in_slips = slips_item ? *slips_item != 0 : derived_slips;
  ++c_.depths;
  return r;
}

}  // namespace plumb::wits
