// CalibrationModel as the plumb/calibration topic type (field for field).
#pragma once

#include "plumb/core/calibration_model.hpp"
#include "plumb/transport/messages.hpp"

namespace plumb::calibrate {

topics::CalibrationCoefficients to_topic(const CalibrationModel& model);

}  // namespace plumb::calibrate
