#include "conversions.hpp"

#include <cstring>
#include <string>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::fastdds {
namespace {

// fixed_string truncates at its bound and at the first NUL without telling anyone; a message that
// arrives different from what was written is worse than an error, so refuse it here.
template <size_t N>
void copy_bounded(const std::string& in, eprosima::fastrtps::fixed_string<N>& out, const char* field) {
  if (in.size() > N) {
    throw Error(std::string("field ") + field + " is " + std::to_string(in.size()) + " characters long, its IDL bound is " +
                std::to_string(N));
  }
  if (std::memchr(in.data(), '\0', in.size()) != nullptr) {
    throw Error(std::string("field ") + field + " contains a NUL character, which an IDL string cannot carry");
  }
  out = in.c_str();
}

template <size_t N> std::string to_std(const eprosima::fastrtps::fixed_string<N>& in) {
  return std::string(in.c_str(), in.size());
}

void check_sequence_size(std::size_t size, std::size_t bound, const char* field) {
  if (size > bound) {
    throw Error(std::string("field ") + field + " has " + std::to_string(size) + " elements, its IDL bound is " +
                std::to_string(bound));
  }
}

void to_fast(const topics::SensorSample& in, plumb::msg::SensorSample& out) {
  out.seq(in.seq);
  out.stamp_ns(in.stamp_ns);
  out.fx(in.fx); out.fy(in.fy); out.fz(in.fz);
  out.bx(in.bx); out.by(in.by); out.bz(in.bz);
  out.wx(in.wx); out.wy(in.wy); out.wz(in.wz);
  out.temp_c(in.temp_c);
  out.flags(in.flags);
}

void from_fast(const plumb::msg::SensorSample& in, topics::SensorSample& out) {
  out.seq = in.seq();
  out.stamp_ns = in.stamp_ns();
  out.fx = in.fx(); out.fy = in.fy(); out.fz = in.fz();
  out.bx = in.bx(); out.by = in.by(); out.bz = in.bz();
  out.wx = in.wx(); out.wy = in.wy(); out.wz = in.wz();
  out.temp_c = in.temp_c();
  out.flags = in.flags();
}

void to_fast(const topics::TriadCalibration& in, plumb::msg::TriadCalibration& out) {
  out.bias(in.bias);
  out.sensitivity(in.sensitivity);
  out.second_order(in.second_order);
  out.bias_temp(in.bias_temp);
  out.scale_temp(in.scale_temp);
}

void from_fast(const plumb::msg::TriadCalibration& in, topics::TriadCalibration& out) {
  out.bias = in.bias();
  out.sensitivity = in.sensitivity();
  out.second_order = in.second_order();
  out.bias_temp = in.bias_temp();
  out.scale_temp = in.scale_temp();
}

}  // namespace

void to_fast(const topics::SensorBatch& in, plumb::msg::SensorBatch& out) {
  copy_bounded(in.tool_id, out.tool_id(), "SensorBatch.tool_id");
  copy_bounded(in.calibration_id, out.calibration_id(), "SensorBatch.calibration_id");
  check_sequence_size(in.samples.size(), topics::kMaxSamplesPerBatch, "SensorBatch.samples");
  auto& samples = out.samples();
  samples.resize(in.samples.size());
  for (std::size_t i = 0; i < in.samples.size(); ++i) to_fast(in.samples[i], samples[i]);
}

void from_fast(const plumb::msg::SensorBatch& in, topics::SensorBatch& out) {
  out.tool_id = to_std(in.tool_id());
  out.calibration_id = to_std(in.calibration_id());
  out.samples.resize(in.samples().size());
  for (std::size_t i = 0; i < in.samples().size(); ++i) from_fast(in.samples()[i], out.samples[i]);
}

void to_fast(const topics::Attitude& in, plumb::msg::Attitude& out) {
  copy_bounded(in.tool_id, out.tool_id(), "Attitude.tool_id");
  copy_bounded(in.estimator, out.estimator(), "Attitude.estimator");
  out.window_start_ns(in.window_start_ns);
  out.window_end_ns(in.window_end_ns);
  out.inclination_deg(in.inclination_deg);
  out.azimuth_deg(in.azimuth_deg);
  out.gravity_toolface_deg(in.gravity_toolface_deg);
  out.magnetic_toolface_deg(in.magnetic_toolface_deg);
  out.rpm(in.rpm);
  out.inclination_sd_deg(in.inclination_sd_deg);
  out.azimuth_sd_deg(in.azimuth_sd_deg);
  out.toolface_sd_deg(in.toolface_sd_deg);
  out.dip_deg(in.dip_deg);
  out.total_g(in.total_g);
  out.total_b(in.total_b);
  out.samples_used(in.samples_used);
  out.flags(in.flags);
  copy_bounded(in.reason, out.reason(), "Attitude.reason");
}

void from_fast(const plumb::msg::Attitude& in, topics::Attitude& out) {
  out.tool_id = to_std(in.tool_id());
  out.estimator = to_std(in.estimator());
  out.window_start_ns = in.window_start_ns();
  out.window_end_ns = in.window_end_ns();
  out.inclination_deg = in.inclination_deg();
  out.azimuth_deg = in.azimuth_deg();
  out.gravity_toolface_deg = in.gravity_toolface_deg();
  out.magnetic_toolface_deg = in.magnetic_toolface_deg();
  out.rpm = in.rpm();
  out.inclination_sd_deg = in.inclination_sd_deg();
  out.azimuth_sd_deg = in.azimuth_sd_deg();
  out.toolface_sd_deg = in.toolface_sd_deg();
  out.dip_deg = in.dip_deg();
  out.total_g = in.total_g();
  out.total_b = in.total_b();
  out.samples_used = in.samples_used();
  out.flags = in.flags();
  out.reason = to_std(in.reason());
}

void to_fast(const topics::CalibrationCoefficients& in, plumb::msg::CalibrationCoefficients& out) {
  copy_bounded(in.tool_id, out.tool_id(), "CalibrationCoefficients.tool_id");
  copy_bounded(in.calibration_id, out.calibration_id(), "CalibrationCoefficients.calibration_id");
  out.stamp_ns(in.stamp_ns);
  out.reference_temp_c(in.reference_temp_c);
  out.temp_min_c(in.temp_min_c);
  out.temp_max_c(in.temp_max_c);
  out.thermometer(in.thermometer);
  to_fast(in.accelerometer, out.accelerometer());
  to_fast(in.magnetometer, out.magnetometer());
}

void from_fast(const plumb::msg::CalibrationCoefficients& in, topics::CalibrationCoefficients& out) {
  out.tool_id = to_std(in.tool_id());
  out.calibration_id = to_std(in.calibration_id());
  out.stamp_ns = in.stamp_ns();
  out.reference_temp_c = in.reference_temp_c();
  out.temp_min_c = in.temp_min_c();
  out.temp_max_c = in.temp_max_c();
  out.thermometer = in.thermometer();
  from_fast(in.accelerometer(), out.accelerometer);
  from_fast(in.magnetometer(), out.magnetometer);
}

void to_fast(const topics::ComponentStatus& in, plumb::msg::ComponentStatus& out) {
  copy_bounded(in.component, out.component(), "ComponentStatus.component");
  copy_bounded(in.host, out.host(), "ComponentStatus.host");
  copy_bounded(in.state, out.state(), "ComponentStatus.state");
  out.stamp_ns(in.stamp_ns);
  constexpr std::size_t kMaxCounters = 32;  // idl/status.idl: sequence<Counter, 32>
  check_sequence_size(in.counters.size(), kMaxCounters, "ComponentStatus.counters");
  auto& counters = out.counters();
  counters.resize(in.counters.size());
  for (std::size_t i = 0; i < in.counters.size(); ++i) {
    copy_bounded(in.counters[i].name, counters[i].name(), "Counter.name");
    counters[i].value(in.counters[i].value);
  }
  copy_bounded(in.last_error, out.last_error(), "ComponentStatus.last_error");
}

void from_fast(const plumb::msg::ComponentStatus& in, topics::ComponentStatus& out) {
  out.component = to_std(in.component());
  out.host = to_std(in.host());
  out.state = to_std(in.state());
  out.stamp_ns = in.stamp_ns();
  out.counters.resize(in.counters().size());
  for (std::size_t i = 0; i < in.counters().size(); ++i) {
    out.counters[i].name = to_std(in.counters()[i].name());
    out.counters[i].value = in.counters()[i].value();
  }
  out.last_error = to_std(in.last_error());
}

void to_fast(const topics::Truth& in, plumb::msg::Truth& out) {
  copy_bounded(in.tool_id, out.tool_id(), "Truth.tool_id");
  out.stamp_ns(in.stamp_ns);
  out.inclination_deg(in.inclination_deg);
  out.azimuth_deg(in.azimuth_deg);
  out.toolface_deg(in.toolface_deg);
  out.rpm(in.rpm);
}

void from_fast(const plumb::msg::Truth& in, topics::Truth& out) {
  out.tool_id = to_std(in.tool_id());
  out.stamp_ns = in.stamp_ns();
  out.inclination_deg = in.inclination_deg();
  out.azimuth_deg = in.azimuth_deg();
  out.toolface_deg = in.toolface_deg();
  out.rpm = in.rpm();
}

}  // namespace plumb::transport::fastdds
