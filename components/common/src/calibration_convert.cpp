#include "plumb/components/calibration_convert.hpp"

#include <cmath>

#include <Eigen/LU>

namespace plumb::components {
namespace {

Eigen::Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
std::array<double, 3> arr(const Eigen::Vector3d& v) { return {v[0], v[1], v[2]}; }

TriadModel to_model(const topics::TriadCalibration& t) {
  TriadModel m;
  m.bias = vec(t.bias);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m.sensitivity(r, c) = t.sensitivity[static_cast<std::size_t>(3 * r + c)];
  m.second_order = vec(t.second_order);
  m.bias_temp = vec(t.bias_temp);
  m.scale_temp = vec(t.scale_temp);
  return m;
}

topics::TriadCalibration to_topic(const TriadModel& m) {
  topics::TriadCalibration t;
  t.bias = arr(m.bias);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) t.sensitivity[static_cast<std::size_t>(3 * r + c)] = m.sensitivity(r, c);
  t.second_order = arr(m.second_order);
  t.bias_temp = arr(m.bias_temp);
  t.scale_temp = arr(m.scale_temp);
  return t;
}

bool finite(const TriadModel& t) {
  return t.bias.allFinite() && t.sensitivity.allFinite() && t.second_order.allFinite() && t.bias_temp.allFinite() &&
         t.scale_temp.allFinite();
}

}  // namespace

CalibrationModel to_model(const topics::CalibrationCoefficients& m) {
  CalibrationModel c;
  c.tool_id = m.tool_id;
  c.calibration_id = m.calibration_id;
  c.stamp_s = static_cast<double>(m.stamp_ns) * 1e-9;
  c.reference_temp_c = m.reference_temp_c;
  c.temp_min_c = m.temp_min_c;
  c.temp_max_c = m.temp_max_c;
  c.thermometer = m.thermometer;
  c.accelerometer = to_model(m.accelerometer);
  c.magnetometer = to_model(m.magnetometer);
  return c;
}

topics::CalibrationCoefficients to_topic(const CalibrationModel& c) {
  topics::CalibrationCoefficients m;
  m.tool_id = c.tool_id.substr(0, topics::Attitude::kToolIdMax);
  m.calibration_id = c.calibration_id.substr(0, topics::CalibrationCoefficients::kCalibrationIdMax);
  m.stamp_ns = std::isfinite(c.stamp_s) ? static_cast<std::int64_t>(std::llround(c.stamp_s * 1e9)) : 0;
  m.reference_temp_c = c.reference_temp_c;
  m.temp_min_c = c.temp_min_c;
  m.temp_max_c = c.temp_max_c;
  m.thermometer = c.thermometer;
  m.accelerometer = to_topic(c.accelerometer);
  m.magnetometer = to_topic(c.magnetometer);
  return m;
}

std::string calibration_problem(const CalibrationModel& c) {
  if (!finite(c.accelerometer)) return "accelerometer coefficients are not finite";
  if (!finite(c.magnetometer)) return "magnetometer coefficients are not finite";
  for (double v : c.thermometer)
    if (!std::isfinite(v)) return "thermometer coefficients are not finite";
  if (!std::isfinite(c.reference_temp_c)) return "reference temperature is not finite";
  // A singular sensitivity matrix would collapse a sensor axis: never what a procedure produces.
  if (std::abs(c.accelerometer.sensitivity.determinant()) < 1e-12) return "accelerometer sensitivity is singular";
  if (std::abs(c.magnetometer.sensitivity.determinant()) < 1e-12) return "magnetometer sensitivity is singular";
  return {};
}

}  // namespace plumb::components
