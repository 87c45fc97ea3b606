#include "conversions.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::cyclonedds {

namespace {

// A bounded IDL string<N> is a char[N + 1] in the generated C code.
template <std::size_t Size>
void put_string(const std::string& value, char (&out)[Size], const char* type, const char* field) {
  constexpr std::size_t bound = Size - 1;
  if (value.size() > bound) {
    throw Error(std::string(type) + "." + field + " is " + std::to_string(value.size()) +
                " characters long, its IDL bound is " + std::to_string(bound));
  }
  if (value.find('\0') != std::string::npos) {
    throw Error(std::string(type) + "." + field + " contains a NUL character");
  }
  std::memcpy(out, value.data(), value.size());
  out[value.size()] = '\0';
}

template <std::size_t Size> std::string get_string(const char (&in)[Size]) {
  return std::string(in, strnlen(in, Size));
}

template <std::size_t N> void put_array(const std::array<double, N>& value, double (&out)[N]) {
  std::copy(value.begin(), value.end(), out);
}
template <std::size_t N> void get_array(const double (&in)[N], std::array<double, N>& value) {
  std::copy(in, in + N, value.begin());
}

void to_c(const topics::SensorSample& m, plumb_msg_SensorSample& c) {
  c.seq = m.seq;
  c.stamp_ns = m.stamp_ns;
  c.fx = m.fx; c.fy = m.fy; c.fz = m.fz;
  c.bx = m.bx; c.by = m.by; c.bz = m.bz;
  c.wx = m.wx; c.wy = m.wy; c.wz = m.wz;
  c.temp_c = m.temp_c;
  c.flags = m.flags;
}

void from_c(const plumb_msg_SensorSample& c, topics::SensorSample& m) {
  m.seq = c.seq;
  m.stamp_ns = c.stamp_ns;
  m.fx = c.fx; m.fy = c.fy; m.fz = c.fz;
  m.bx = c.bx; m.by = c.by; m.bz = c.bz;
  m.wx = c.wx; m.wy = c.wy; m.wz = c.wz;
  m.temp_c = c.temp_c;
  m.flags = c.flags;
}

void to_c(const topics::TriadCalibration& m, plumb_msg_TriadCalibration& c) {
  put_array(m.bias, c.bias);
  put_array(m.sensitivity, c.sensitivity);
  put_array(m.second_order, c.second_order);
  put_array(m.bias_temp, c.bias_temp);
  put_array(m.scale_temp, c.scale_temp);
}

void from_c(const plumb_msg_TriadCalibration& c, topics::TriadCalibration& m) {
  get_array(c.bias, m.bias);
  get_array(c.sensitivity, m.sensitivity);
  get_array(c.second_order, m.second_order);
  get_array(c.bias_temp, m.bias_temp);
  get_array(c.scale_temp, m.scale_temp);
}

}  // namespace

void to_c(const topics::SensorBatch& m, plumb_msg_SensorBatch& c, OutgoingBuffers& buffers) {
  constexpr const char* type = "SensorBatch";
  put_string(m.tool_id, c.tool_id, type, "tool_id");
  put_string(m.calibration_id, c.calibration_id, type, "calibration_id");
  if (m.samples.size() > topics::kMaxSamplesPerBatch) {
    throw Error("SensorBatch holds " + std::to_string(m.samples.size()) + " samples, at most " +
                std::to_string(topics::kMaxSamplesPerBatch) + " fit in one batch");
  }
  for (std::size_t i = 0; i < m.samples.size(); ++i) to_c(m.samples[i], buffers.samples[i]);
  c.samples._maximum = static_cast<std::uint32_t>(m.samples.size());
  c.samples._length = static_cast<std::uint32_t>(m.samples.size());
  c.samples._buffer = buffers.samples.data();
  c.samples._release = false;  // points into `buffers`, never freed by Cyclone
}

void to_c(const topics::Attitude& m, plumb_msg_Attitude& c, OutgoingBuffers&) {
  constexpr const char* type = "Attitude";
  put_string(m.tool_id, c.tool_id, type, "tool_id");
  put_string(m.estimator, c.estimator, type, "estimator");
  c.window_start_ns = m.window_start_ns;
  c.window_end_ns = m.window_end_ns;
  c.inclination_deg = m.inclination_deg;
  c.azimuth_deg = m.azimuth_deg;
  c.gravity_toolface_deg = m.gravity_toolface_deg;
  c.magnetic_toolface_deg = m.magnetic_toolface_deg;
  c.rpm = m.rpm;
  c.inclination_sd_deg = m.inclination_sd_deg;
  c.azimuth_sd_deg = m.azimuth_sd_deg;
  c.toolface_sd_deg = m.toolface_sd_deg;
  c.dip_deg = m.dip_deg;
  c.total_g = m.total_g;
  c.total_b = m.total_b;
  c.samples_used = m.samples_used;
  c.flags = m.flags;
  put_string(m.reason, c.reason, type, "reason");
}

void to_c(const topics::CalibrationCoefficients& m, plumb_msg_CalibrationCoefficients& c, OutgoingBuffers&) {
  constexpr const char* type = "CalibrationCoefficients";
  put_string(m.tool_id, c.tool_id, type, "tool_id");
  put_string(m.calibration_id, c.calibration_id, type, "calibration_id");
  c.stamp_ns = m.stamp_ns;
  c.reference_temp_c = m.reference_temp_c;
  c.temp_min_c = m.temp_min_c;
  c.temp_max_c = m.temp_max_c;
  put_array(m.thermometer, c.thermometer);
  to_c(m.accelerometer, c.accelerometer);
  to_c(m.magnetometer, c.magnetometer);
}

void to_c(const topics::ComponentStatus& m, plumb_msg_ComponentStatus& c, OutgoingBuffers& buffers) {
  constexpr const char* type = "ComponentStatus";
  put_string(m.component, c.component, type, "component");
  put_string(m.host, c.host, type, "host");
  put_string(m.state, c.state, type, "state");
  c.stamp_ns = m.stamp_ns;
  if (m.counters.size() > topics::kMaxCountersPerStatus) {
    throw Error("ComponentStatus holds " + std::to_string(m.counters.size()) + " counters, at most " +
                std::to_string(topics::kMaxCountersPerStatus) + " fit");
  }
  for (std::size_t i = 0; i < m.counters.size(); ++i) {
    put_string(m.counters[i].name, buffers.counters[i].name, "Counter", "name");
    buffers.counters[i].value = m.counters[i].value;
  }
  c.counters._maximum = static_cast<std::uint32_t>(m.counters.size());
  c.counters._length = static_cast<std::uint32_t>(m.counters.size());
  c.counters._buffer = buffers.counters.data();
  c.counters._release = false;
  put_string(m.last_error, c.last_error, type, "last_error");
}

void to_c(const topics::Truth& m, plumb_msg_Truth& c, OutgoingBuffers&) {
  put_string(m.tool_id, c.tool_id, "Truth", "tool_id");
  c.stamp_ns = m.stamp_ns;
  c.inclination_deg = m.inclination_deg;
  c.azimuth_deg = m.azimuth_deg;
  c.toolface_deg = m.toolface_deg;
  c.rpm = m.rpm;
}

void from_c(const plumb_msg_SensorBatch& c, topics::SensorBatch& m) {
  m.tool_id = get_string(c.tool_id);
  m.calibration_id = get_string(c.calibration_id);
  m.samples.resize(c.samples._length);
  for (std::uint32_t i = 0; i < c.samples._length; ++i) from_c(c.samples._buffer[i], m.samples[i]);
}

void from_c(const plumb_msg_Attitude& c, topics::Attitude& m) {
  m.tool_id = get_string(c.tool_id);
  m.estimator = get_string(c.estimator);
  m.window_start_ns = c.window_start_ns;
  m.window_end_ns = c.window_end_ns;
  m.inclination_deg = c.inclination_deg;
  m.azimuth_deg = c.azimuth_deg;
  m.gravity_toolface_deg = c.gravity_toolface_deg;
  m.magnetic_toolface_deg = c.magnetic_toolface_deg;
  m.rpm = c.rpm;
  m.inclination_sd_deg = c.inclination_sd_deg;
  m.azimuth_sd_deg = c.azimuth_sd_deg;
  m.toolface_sd_deg = c.toolface_sd_deg;
  m.dip_deg = c.dip_deg;
  m.total_g = c.total_g;
  m.total_b = c.total_b;
  m.samples_used = c.samples_used;
  m.flags = c.flags;
  m.reason = get_string(c.reason);
}

void from_c(const plumb_msg_CalibrationCoefficients& c, topics::CalibrationCoefficients& m) {
  m.tool_id = get_string(c.tool_id);
  m.calibration_id = get_string(c.calibration_id);
  m.stamp_ns = c.stamp_ns;
  m.reference_temp_c = c.reference_temp_c;
  m.temp_min_c = c.temp_min_c;
  m.temp_max_c = c.temp_max_c;
  get_array(c.thermometer, m.thermometer);
  from_c(c.accelerometer, m.accelerometer);
  from_c(c.magnetometer, m.magnetometer);
}

void from_c(const plumb_msg_ComponentStatus& c, topics::ComponentStatus& m) {
  m.component = get_string(c.component);
  m.host = get_string(c.host);
  m.state = get_string(c.state);
  m.stamp_ns = c.stamp_ns;
  m.counters.resize(c.counters._length);
  for (std::uint32_t i = 0; i < c.counters._length; ++i) {
    m.counters[i].name = get_string(c.counters._buffer[i].name);
    m.counters[i].value = c.counters._buffer[i].value;
  }
  m.last_error = get_string(c.last_error);
}

void from_c(const plumb_msg_Truth& c, topics::Truth& m) {
  m.tool_id = get_string(c.tool_id);
  m.stamp_ns = c.stamp_ns;
  m.inclination_deg = c.inclination_deg;
  m.azimuth_deg = c.azimuth_deg;
  m.toolface_deg = c.toolface_deg;
  m.rpm = c.rpm;
}

}  // namespace plumb::transport::cyclonedds
