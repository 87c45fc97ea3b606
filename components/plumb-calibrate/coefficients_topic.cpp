#include "coefficients_topic.hpp"

#include <cmath>

namespace plumb::calibrate {

namespace {

topics::TriadCalibration triad(const TriadModel& m) {
  topics::TriadCalibration t;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    t.bias[i] = m.bias[k];
    t.second_order[i] = m.second_order[k];
    t.bias_temp[i] = m.bias_temp[k];
    t.scale_temp[i] = m.scale_temp[k];
    for (std::size_t j = 0; j < 3; ++j) t.sensitivity[3 * i + j] = m.sensitivity(k, static_cast<Eigen::Index>(j));
  }
  return t;
}

}  // namespace

topics::CalibrationCoefficients to_topic(const CalibrationModel& c) {
  topics::CalibrationCoefficients m;
  m.tool_id = c.tool_id.substr(0, topics::kToolIdMax);
  m.calibration_id = c.calibration_id.substr(0, topics::kIdMax);
  m.stamp_ns = std::isfinite(c.stamp_s) ? static_cast<std::int64_t>(std::llround(c.stamp_s * 1e9)) : 0;
  m.reference_temp_c = c.reference_temp_c;
  m.temp_min_c = c.temp_min_c;
  m.temp_max_c = c.temp_max_c;
  m.thermometer = c.thermometer;
  m.accelerometer = triad(c.accelerometer);
  m.magnetometer = triad(c.magnetometer);
  return m;
}

}  // namespace plumb::calibrate
