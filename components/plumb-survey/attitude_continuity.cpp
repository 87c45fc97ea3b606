#include "attitude_continuity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace plumb::survey_component {

std::uint64_t AttitudeContinuity::add(double t_start, double t_end) {
  std::uint64_t missing = 0;
  if (have_) {
    // The longest window seen is the configured one: the window before a gap is often a partial
    // one (the host publishes what it holds when its input goes silent).
    length_ = std::max(length_, last_end_ - last_start_);
    const double length = length_;
    const double gap = t_start - last_end_;
    if (t_start <= last_start_) {
      ++out_of_order_;  // a restarted source (the simulator from t = 0) or a duplicate
    } else if (length > 0 && gap >= length / 2) {
      missing = static_cast<std::uint64_t>(std::llround(gap / length));
      ++gaps_;
      missing_ += missing;
      char text[160];
      std::snprintf(text, sizeof text, "attitude gap of %.2f s before the window starting at t = %.3f s (%llu windows missing)",
                    gap, t_start, static_cast<unsigned long long>(missing));
      note_ = text;
    }
  }
  have_ = true;
  last_start_ = t_start;
  last_end_ = t_end;
  return missing;
}

}  // namespace plumb::survey_component
