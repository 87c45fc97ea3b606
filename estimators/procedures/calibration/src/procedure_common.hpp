// Pieces the procedures share (private to the library).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/calibration/procedures.hpp"

namespace plumb::calibration::detail {

// Runs a procedure body; a CalibrationError (or any exception) becomes Outcome::error and the
// warnings gathered so far are kept.
Outcome run_guarded(const std::function<Result(std::vector<std::string>& warnings)>& body);

// Appends parameters named prefix + names[i] with values and the sds from the covariance diagonal.
void add_parameters(std::vector<Parameter>& out, const std::string& prefix, const std::vector<std::string>& names,
                    const Eigen::VectorXd& values, const Eigen::MatrixXd& covariance, const std::string& unit = "");

// Temperature difference from the reference for a station (0 without a thermometer).
double station_dT(const CalibrationModel& m, const StationAverage& s);

// Residuals of every station against the model (orientation known: direction and inclination
// before/after; unknown: only the norm). Adds a warning per station beyond warn_deg.
std::vector<StationResidual> accel_residuals(const CalibrationModel& model, const CalibrationModel& nominal,
                                             const std::vector<StationAverage>& stations, double g, double warn_deg,
                                             std::vector<std::string>& warnings);

void fill_identity(Result& r, const CommonOptions& o);

// Splits the stations' direction errors after calibration into the part the turntable rotations
// of a face share (the sensor model's) and the part that turns with the table (table tilt,
// misplaced stations). Stations grouped by run and face; faces with fewer than 2 stations count
// only toward the sensor part.
ResidualSplit split_residuals(const CalibrationModel& model, const std::vector<StationAverage>& stations);

// The samples-and-stations form of a procedure: averages the stations (a station that never
// settles becomes the outcome's error), then runs the procedure on the averages.
template <class Options, class Procedure>
Outcome from_samples(const std::vector<Sample>& samples, const std::vector<Station>& stations, const Options& options,
                     const SettleOptions& settle, Procedure procedure) {
  std::vector<StationAverage> averages;
  try {
    averages = average_stations(samples, stations, settle);
  } catch (const std::exception& e) {
    Outcome o;
    o.error = e.what();
    return o;
  }
  Outcome out = procedure(averages, options);
  // What the averaging left out (motion) goes into the warnings of the outcome and its result.
  std::vector<std::string> notes;
  for (const auto& a : averages) notes.insert(notes.end(), a.notes.begin(), a.notes.end());
  out.warnings.insert(out.warnings.begin(), notes.begin(), notes.end());
  if (out.result) out.result->warnings = out.warnings;
  return out;
}

std::string format(double x, int precision = 4);

}  // namespace plumb::calibration::detail
