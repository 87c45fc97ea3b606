// Runs the chosen procedure and writes its outputs: shared by the offline and live modes.
#pragma once

#include <vector>

#include "options.hpp"
#include "plumb/calibration/procedures.hpp"
#include "plumb/calibration/types.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::calibrate_component {

calibration::Outcome run_procedure(const Options& o, const std::vector<Sample>& samples,
                                   const std::vector<calibration::Station>& stations);

// Writes the report (always, when asked) and the coefficients (only on success); prints a summary.
// Returns the process exit code: 0 on success, 1 on a failed procedure.
int write_outputs(const Options& o, const calibration::Outcome& outcome);

// Publishes the coefficients on plumb/calibration (transient-local) and keeps the writer for
// linger_s seconds so late joiners get them. Only ever called with a successful outcome.
void publish_coefficients(const Options& o, const CalibrationModel& model);

}  // namespace plumb::calibrate_component
