// A tool code file: the terms of an ISCWSA error model of one's own (a MEMS package is not an MWD
// tool), in the layout of docs/conventions.md "Tool code file".
#pragma once

#include <istream>
#include <string>

#include "plumb/survey/iscwsa.hpp"

namespace plumb::survey::iscwsa {

// '#' comments, of which these lines are read: "# tortuosity_rad_per_m V", "# revision N", "#
// xy_accelerometer_cant_deg V", and the gyro model's running: "# gyro_static_inc_deg FROM TO", "#
// gyro_continuous_inc_deg FROM TO", "# gyro_initialisation gyrocompass|reference", "#
// gyro_initialisation_inc_deg V", "# gyro_running_speed_m_per_h V", "# gyro_noise_reduction_factor
// V", "# gyro_z_drift_inc_deg FROM TO", "# gyro_xy_drift_inc_deg FROM TO" (docs/surveys.md). Then
// the header `code,weight_function,magnitude,unit,propagation` and one row per term; propagation
// R, S, G or W. Throws std::runtime_error naming the source and line.
ToolCode read_tool_code(std::istream& in, const std::string& source);

}  // namespace plumb::survey::iscwsa
