#include "attitude_continuity.hpp"

#include <cmath>
#include <cstdio>

namespace plumb::survey_component {

std::uint64_t AttitudeContinuity::add(double t_start, double t_end) {
  std::uint64_t missing = 0;
  if (have_) {
    const double length = last_end_ - last_start_;
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
