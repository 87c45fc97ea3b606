// The built-in gyro tool codes (iscwsa_gyro_tool_codes.cpp), beside the MWD ones of
// iscwsa_tool_codes.cpp. Internal to the survey library.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "plumb/survey/iscwsa.hpp"

namespace plumb::survey::iscwsa::detail {

std::vector<std::string> gyro_tool_code_names();
std::optional<ToolCode> builtin_gyro_tool_code(const std::string& name);  // nullopt: not a gyro code's name

// A strapdown triad's figures, in the units of its datasheet.
struct StrapdownFigures {
  double gyro_bias_dph, gyro_arw_deg_rt_h, accel_bias_mg, accel_scale_ppm, accel_misalignment_mrad;
};
// A strapdown triad run continuously from the survey's first station over the stations' own times:
// revision 5's depth, misalignment and course-length terms, SAGE, the accelerometers' bias (z),
// scale factor and misalignment, and the gyros' drift (GXYZ-GD) and random walk (GXYZ-GRW),
// initialised from a reference. How the run was initialised (EXT-REF, or a gyrocompass's terms) is
// the caller's to add.
ToolCode strapdown_run(const std::string& name, const StrapdownFigures& figures);

}  // namespace plumb::survey::iscwsa::detail
