// Vendor-neutral C++ mirror of the topic types in idl/*.idl. Components and examples use these;
// each transport plugin converts them to and from its vendor's generated types. A test
// (tests/unit/transports/idl_mirror_test) checks field by field that this file matches idl/.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace plumb::topics {

inline constexpr std::uint32_t kMaxSamplesPerBatch = 32;
inline constexpr std::uint32_t kMaxCountersPerStatus = 32;  // ComponentStatus.counters bound

// SensorSample.flags (idl/sensor.idl SAMPLE_*).
namespace sample_flags {
inline constexpr std::uint32_t kAccelSaturated = 1;
inline constexpr std::uint32_t kMagSaturated = 2;
inline constexpr std::uint32_t kGyroSaturated = 4;
inline constexpr std::uint32_t kOutOfRange = 8;
inline constexpr std::uint32_t kNotFinite = 16;
inline constexpr std::uint32_t kGapBefore = 32;
inline constexpr std::uint32_t kTimeBackwards = 64;
inline constexpr std::uint32_t kHasGyro = 128;
inline constexpr std::uint32_t kHasTemperature = 256;
inline constexpr std::uint32_t kCalibrated = 512;
inline constexpr std::uint32_t kTemperatureOutOfRange = 1024;
}  // namespace sample_flags

// Attitude.flags (idl/attitude.idl ATTITUDE_*).
namespace attitude_flags {
inline constexpr std::uint32_t kValid = 1;
inline constexpr std::uint32_t kAzimuthValid = 2;
inline constexpr std::uint32_t kToolfaceValid = 4;
inline constexpr std::uint32_t kRotating = 8;
inline constexpr std::uint32_t kPartialWindow = 16;
}  // namespace attitude_flags

// Bounded IDL strings: string<N> holds at most N characters; writers reject longer ones.
inline constexpr std::size_t kToolIdMax = 31;
inline constexpr std::size_t kNameMax = 31;
inline constexpr std::size_t kIdMax = 63;
inline constexpr std::size_t kReasonMax = 63;
inline constexpr std::size_t kStateMax = 15;
inline constexpr std::size_t kErrorMax = 127;
inline constexpr std::size_t kComponentMax = 63;  // ComponentStatus.component
inline constexpr std::size_t kHostMax = 63;       // ComponentStatus.host

struct SensorSample {
  std::uint64_t seq = 0;
  std::int64_t stamp_ns = 0;
  double fx = 0, fy = 0, fz = 0;
  double bx = 0, by = 0, bz = 0;
  double wx = 0, wy = 0, wz = 0;
  double temp_c = 0;
  std::uint32_t flags = 0;
  bool operator==(const SensorSample&) const = default;
};

struct SensorBatch {
  std::string tool_id;         // <= 31
  std::string calibration_id;  // <= 63
  std::vector<SensorSample> samples;  // <= kMaxSamplesPerBatch
  bool operator==(const SensorBatch&) const = default;
};

struct Attitude {
  std::string tool_id;    // <= 31
  std::string estimator;  // <= 31
  std::int64_t window_start_ns = 0;
  std::int64_t window_end_ns = 0;
  double inclination_deg = 0;
  double azimuth_deg = 0;
  double gravity_toolface_deg = 0;
  double magnetic_toolface_deg = 0;
  double rpm = 0;
  double inclination_sd_deg = 0;
  double azimuth_sd_deg = 0;
  double toolface_sd_deg = 0;
  double dip_deg = 0;
  double total_g = 0;
  double total_b = 0;
  std::uint32_t samples_used = 0;
  std::uint32_t flags = 0;
  std::string reason;  // <= 63
  bool operator==(const Attitude&) const = default;
};

struct TriadCalibration {
  std::array<double, 3> bias{};
  std::array<double, 9> sensitivity{1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::array<double, 3> second_order{};
  std::array<double, 3> bias_temp{};
  std::array<double, 3> scale_temp{};
  bool operator==(const TriadCalibration&) const = default;
};

struct CalibrationCoefficients {
  std::string tool_id;         // <= 31
  std::string calibration_id;  // <= 63
  std::int64_t stamp_ns = 0;
  double reference_temp_c = 25;
  double temp_min_c = -40;
  double temp_max_c = 200;
  std::array<double, 4> thermometer{0, 1, 0, 0};
  TriadCalibration accelerometer;
  TriadCalibration magnetometer;
  bool operator==(const CalibrationCoefficients&) const = default;
};

struct Counter {
  std::string name;  // <= 31
  std::uint64_t value = 0;
  bool operator==(const Counter&) const = default;
};

struct ComponentStatus {
  std::string component;  // <= 63
  std::string host;       // <= 63
  std::string state;      // <= 15
  std::int64_t stamp_ns = 0;
  std::vector<Counter> counters;  // <= 32
  std::string last_error;         // <= 127
  bool operator==(const ComponentStatus&) const = default;
};

struct Truth {
  std::string tool_id;  // <= 31
  std::int64_t stamp_ns = 0;
  double inclination_deg = 0;
  double azimuth_deg = 0;
  double toolface_deg = 0;
  double rpm = 0;
  bool operator==(const Truth&) const = default;
};

// Field visitors: v(name, member) for every field in IDL order; nested structs and sequences are
// passed as they are. Used by `plumb topic echo/pub`, the CSV output and the IDL mirror test.
template <class M, class V> void visit_fields(M& m, V&& v) requires std::is_same_v<std::remove_const_t<M>, SensorSample> {
  v("seq", m.seq); v("stamp_ns", m.stamp_ns);
  v("fx", m.fx); v("fy", m.fy); v("fz", m.fz);
  v("bx", m.bx); v("by", m.by); v("bz", m.bz);
  v("wx", m.wx); v("wy", m.wy); v("wz", m.wz);
  v("temp_c", m.temp_c); v("flags", m.flags);
}
template <class M, class V> void visit_fields(M& m, V&& v) requires std::is_same_v<std::remove_const_t<M>, SensorBatch> {
  v("tool_id", m.tool_id); v("calibration_id", m.calibration_id); v("samples", m.samples);
}
template <class M, class V> void visit_fields(M& m, V&& v) requires std::is_same_v<std::remove_const_t<M>, Attitude> {
  v("tool_id", m.tool_id); v("estimator", m.estimator);
  v("window_start_ns", m.window_start_ns); v("window_end_ns", m.window_end_ns);
  v("inclination_deg", m.inclination_deg); v("azimuth_deg", m.azimuth_deg);
  v("gravity_toolface_deg", m.gravity_toolface_deg); v("magnetic_toolface_deg", m.magnetic_toolface_deg);
  v("rpm", m.rpm); v("inclination_sd_deg", m.inclination_sd_deg); v("azimuth_sd_deg", m.azimuth_sd_deg);
  v("toolface_sd_deg", m.toolface_sd_deg); v("dip_deg", m.dip_deg); v("total_g", m.total_g);
  v("total_b", m.total_b); v("samples_used", m.samples_used); v("flags", m.flags); v("reason", m.reason);
}
template <class M, class V> void visit_fields(M& m, V&& v) requires std::is_same_v<std::remove_const_t<M>, TriadCalibration> {
  v("bias", m.bias); v("sensitivity", m.sensitivity); v("second_order", m.second_order);
  v("bias_temp", m.bias_temp); v("scale_temp", m.scale_temp);
}
template <class M, class V> void visit_fields(M& m, V&& v) requires std::is_same_v<std::remove_const_t<M>, CalibrationCoefficients> {
  v("tool_id", m.tool_id); v("calibration_id", m.calibration_id); v("stamp_ns", m.stamp_ns);
  v("reference_temp_c", m.reference_temp_c); v("temp_min_c", m.temp_min_c); v("temp_max_c", m.temp_max_c);
  v("thermometer", m.thermometer); v("accelerometer", m.accelerometer); v("magnetometer", m.magnetometer);
}
template <class M, class V> void visit_fields(M& m, V&& v) requires std::is_same_v<std::remove_const_t<M>, Counter> {
  v("name", m.name); v("value", m.value);
}
template <class M, class V> void visit_fields(M& m, V&& v) requires std::is_same_v<std::remove_const_t<M>, ComponentStatus> {
  v("component", m.component); v("host", m.host); v("state", m.state); v("stamp_ns", m.stamp_ns);
  v("counters", m.counters); v("last_error", m.last_error);
}
template <class M, class V> void visit_fields(M& m, V&& v) requires std::is_same_v<std::remove_const_t<M>, Truth> {
  v("tool_id", m.tool_id); v("stamp_ns", m.stamp_ns); v("inclination_deg", m.inclination_deg);
  v("azimuth_deg", m.azimuth_deg); v("toolface_deg", m.toolface_deg); v("rpm", m.rpm);
}

}  // namespace plumb::topics
