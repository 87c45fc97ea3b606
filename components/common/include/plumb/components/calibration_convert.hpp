// Calibration coefficients between the topic type (plumb/calibration) and the model that
// applies them (plumb::CalibrationModel). Field for field; no interpretation.
#pragma once

#include <string>

#include "plumb/core/calibration_model.hpp"
#include "plumb/topics/all.hpp"

namespace plumb::components {

CalibrationModel to_model(const topics::CalibrationCoefficients& m);
topics::CalibrationCoefficients to_topic(const CalibrationModel& model);

// Why a received model cannot be applied (non-finite or singular coefficients), empty if it can.
std::string calibration_problem(const CalibrationModel& model);

}  // namespace plumb::components
