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

}  // namespace plumb::survey::iscwsa::detail
