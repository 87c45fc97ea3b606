// The coefficients text file of a CalibrationModel (docs/calibration.md): "key value..." lines,
// '#' comments, versions 1 and 2.
#pragma once

#include <iosfwd>
#include <string>

#include "plumb/core/calibration_model.hpp"

namespace plumb::csv {

// Throw std::runtime_error naming the file and line on a bad file.
CalibrationModel read_calibration_file(const std::string& path);
CalibrationModel parse_calibration(std::istream& in, const std::string& source_name);
// Writes the oldest version that holds the model (version 1 unless it has version-2 terms).
void write_calibration(std::ostream& out, const CalibrationModel& model);

}  // namespace plumb::csv
