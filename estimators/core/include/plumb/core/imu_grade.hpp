// The typical figures of the three inertial sensor classes a tool is built from: the simulator's
// grades (sim/src/imu_grade.cpp), the navigator's `imu_grade` presets (estimators/plugins/strapdown
// parameters) and the survey's error model of a navigator's stations
// (plumb/survey/navigator_tool_code.hpp) read the same table, so a survey is held to the very
// figures its navigator assumed, of the sensors the simulator made. It lives in the vocabulary
// because all three need it and none may depend on another: the survey library is plain math
// without the navigator, and the simulator knows the vocabulary only.
#pragma once

#include <string_view>

namespace plumb {

struct ImuGradeFigures {
  const char* name;
  double gyro_bias_dph;            // turn-on bias, 1 sigma per axis (deg/h)
  double gyro_arw_deg_rt_h;        // angle random walk (deg/sqrt(h))
  double accel_bias_mg;            // turn-on bias, 1 sigma per axis (mg)
  double accel_vrw_mps_rt_h;       // velocity random walk (m/s/sqrt(h))
  double gyro_scale_ppm, gyro_misalignment_mrad, gyro_g_dph_g;
  double accel_scale_ppm, accel_misalignment_mrad;
  double gyro_range_dps, accel_range_g;      // the class's usual ranges
  double gyro_temp_dph_c, accel_temp_mg_c;   // typical bias temperature coefficients
};

// The classes as sim/include/plumb/sim/imu_model.hpp describes them.
inline constexpr ImuGradeFigures kImuGrades[] = {
    {"navigation", 0.01, 0.002, 0.025, 0.005, 5, 0.02, 0.1, 20, 0.02, 500, 25, 0.002, 0.002},
    {"tactical", 1.0, 0.05, 0.3, 0.03, 100, 0.1, 1, 100, 0.1, 1000, 40, 0.05, 0.01},
    {"mems", 10.0, 0.3, 2.0, 0.06, 1000, 1.0, 10, 500, 0.5, 2000, 16, 0.2, 0.05}};

// The grade of that name, or nullptr.
inline const ImuGradeFigures* find_imu_grade(std::string_view name) {
  for (const ImuGradeFigures& g : kImuGrades)
    if (name == g.name) return &g;
  return nullptr;
}

}  // namespace plumb
