// The ISCWSA gyro model of the strapdown navigator's own stations, from the navigator's own
// parameters: its IMU's figures (imu_grade's presets, plumb/core/imu_grade.hpp, where a figure is
// not given) run continuously from its alignment over the stations' times, initialised the way it
// aligned:
//   gyrocompass=1          the gyrocompass's terms (GXYZ-XYB1, -XYB2, -ZB: the gyro bias; GXYZ-XYRN,
//                          -ZRN: the gyro noise averaged over the alignment, align_s), at the first
//                          station's inclination and the well's latitude (latitude_deg);
//   initial_azimuth_deg    EXT-REF = initial_azimuth_sd_deg, with no floor: 0 says the azimuth is
//                          exact (the navigator's frame is then relative to it, and its filter holds
//                          it exact too);
//   the magnetometer       EXT-REF = the magnetic azimuth's sigma at alignment: the heading's model
//                          error (mag_heading_sd_deg) and the drill string's axial magnetisation
//                          (mag_axial_bias_uT) at its worst, a horizontal tool pointing east or
//                          west, b / (B cos dip) (0.69 deg at the defaults, 0.3 uT in 50 uT at 60 deg);
//   none of them           EXT-REF 0: the frame is the alignment's own (relative).
// The gyro figures: GXYZ-GD the gyro bias (gyro_bias_dph), GXYZ-GRW its random walk
// (gyro_arw_deg_rt_h); the accelerometers' bias, scale factor and misalignment; the depth,
// tool-misalignment and course-length terms of the ISCWSA revision 5 codes.
// The navigator's bias instability, scale factor and g-sensitivity have no term of the model and
// are left out; its magnetic azimuth updates at stops (use_magnetometer) are not modelled either
// (the model's drift then overstates what a magnetically aided navigator drifts).
#pragma once

#include <map>
#include <string>

#include "plumb/survey/iscwsa.hpp"

namespace plumb::survey::iscwsa {

// Every parameter of the strapdown navigator with its value in use, as `plumb param dump` gives
// them (an empty value: the plugin's own, e.g. imu_grade's preset).
using NavigatorParameters = std::map<std::string, std::string>;

struct NavigatorModel {
  // Named within the survey message's 63 characters, without a comma (a CSV column of the survey
  // file): "GYRO:navigator (tactical; magnetic az
  // 0.689 deg)", the grade followed by its gyro bias where a figure is not the grade's.
  ToolCode tool;
  double latitude_deg;  // the navigator's latitude_deg: a gyrocompass's terms need it
  std::string initialisation;  // "gyrocompass", "given azimuth", "magnetic azimuth" or "relative azimuth"
};

// `reference_b_uT` and `reference_dip_deg` serve the magnetic alignment's sigma where the navigator
// learnt its field from the data (field_uT, dip_deg empty). Throws std::invalid_argument naming a
// parameter that is missing or not a number, or an unknown imu_grade.
NavigatorModel navigator_tool_code(const NavigatorParameters& parameters, double reference_b_uT = 50,
                                   double reference_dip_deg = 60);

}  // namespace plumb::survey::iscwsa
