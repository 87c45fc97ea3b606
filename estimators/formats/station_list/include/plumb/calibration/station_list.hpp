// The station list file (docs/calibration.md): which part of a recording is which station.
//
//   # comments
//   name,start_s,end_s,orientation,run,ref_temp_c
//   p+x,0,60,+x,,
//   25C/+x@90,65,125,+x@90,25C,25.01;24.98;25.03
//
// name, start_s, end_s (seconds, the sensor CSV's t) and orientation (+x -x +y -y +z -z, with
// @0/@90/@180/@270 for the turntable rotation, or "any") are required; run (temperature run) and
// ref_temp_c (reference thermometer readings separated by ';') are optional. Column order is free.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "plumb/calibration/types.hpp"

namespace plumb::calibration {

// Throws CalibrationError naming the file and line.
std::vector<Station> parse_station_list(std::istream& in, const std::string& source);
std::vector<Station> read_station_list(const std::string& path);
void write_station_list(std::ostream& out, const std::vector<Station>& stations);

}  // namespace plumb::calibration
