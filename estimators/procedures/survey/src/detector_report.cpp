#include "plumb/survey/detector_report.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

namespace plumb::survey {

std::string describe_windows(const DetectorCounters& c) {
  std::ostringstream o;
  o << c.windows << " attitude windows: " << c.invalid_windows << " invalid";
  if (!c.invalid_reasons.empty()) {
    std::vector<std::pair<std::string, std::uint64_t>> reasons(c.invalid_reasons.begin(), c.invalid_reasons.end());
    std::sort(reasons.begin(), reasons.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    o << " (";
    for (std::size_t i = 0; i < reasons.size(); ++i) o << (i ? ", " : "") << reasons[i].second << " " << reasons[i].first;
    o << ")";
  }
  o << ", " << c.moving_windows << " while the depth moved, " << c.no_depth_windows << " without depth, "
    << c.combined_windows << " combined into stations, " << c.same_stop_windows << " more in a stop, " << c.repeat_stops
    << " repeated stop(s)";
  return o.str();
}

std::string no_station_advice(const DetectorCounters& c, const std::string& estimator, double tolerance) {
  std::ostringstream o;
  o << "no station found (" << describe_windows(c) << ")";
  const auto valid = c.windows - c.invalid_windows - c.old_windows;
  if (c.windows == 0) {
    o << ": no attitude window at all; is the input long enough for one window?";
  } else if (c.invalid_windows * 2 > c.windows) {
    o << ": most windows were invalid for '" << estimator << "'";
    if (estimator == "static")
      o << "; on a turning platform try -e compensated (it fits the rotation)";
    else
      o << "; try another estimator (-e static on a standing tool, -e compensated on a turning one) or a longer --window";
  } else if (c.no_depth_windows * 2 > valid) {
    o << ": the depth did not cover the windows (reports more than 2 s apart?); check the depth input's clock";
  } else if (c.moving_windows * 2 > valid) {
    o << ": the depth never stood still within " << tolerance
      << " m; give the depth's sigma (--depth-sd) or a larger --still-tolerance, or a shorter --min-still";
  }
  return o.str();
}

}  // namespace plumb::survey
