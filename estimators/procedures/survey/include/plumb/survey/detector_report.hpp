// What the station detector did with the attitude windows, in words: the counts by fate (invalid
// ones by the estimator's reason), and, when no station was found, what to try.
#pragma once

#include <string>

#include "plumb/survey/station_detector.hpp"

namespace plumb::survey {

// "185 attitude windows: 181 invalid (181 rotating, ...), 4 while the depth moved, ..."
std::string describe_windows(const DetectorCounters& c);

// Why no station was found and what to try, from the counts; `estimator` names the estimator used
// and `depth_tolerance_m` the still tolerance in force.
std::string no_station_advice(const DetectorCounters& c, const std::string& estimator, double depth_tolerance_m);

}  // namespace plumb::survey
