// The calibration report (docs/calibration.md): outcome, warnings, parameters with standard
// deviations, per-station residuals and the before/after inclination error.
#pragma once

#include <string>

#include "plumb/calibration/types.hpp"

namespace plumb::calibration {

std::string format_report(const Outcome& outcome, const std::string& procedure);

// Largest before/after inclination error over the stations with a known orientation (-1: none).
void inclination_summary(const Result& r, double& before_deg, double& after_deg);

}  // namespace plumb::calibration
