// One sensor sample in the tool frame, per docs/conventions.md. This is the math libraries'
// own type (no DDS); components convert it to and from plumb::topics::SensorSample.
#pragma once

#include <cstdint>

#include <Eigen/Core>

namespace plumb {

// Sample::flags bits: the same values as idl/sensor.idl SAMPLE_*.
namespace flags {
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
// Not on the wire (depth travels on its own topic): the sample carries a measured depth.
inline constexpr std::uint32_t kHasDepth = 2048;
// The sample has no magnetometer reading (a gyro tool, a logger without one): b is meaningless.
inline constexpr std::uint32_t kNoMagnetometer = 4096;
// Samples carrying any of these must not be used for attitude.
inline constexpr std::uint32_t kUnusable = kAccelSaturated | kMagSaturated | kOutOfRange | kNotFinite | kTimeBackwards;
}  // namespace flags

struct Sample {
  std::uint64_t seq = 0;
  double t = 0;                                  // s
  Eigen::Vector3d f = Eigen::Vector3d::Zero();   // specific force, m/s^2 (at rest f = -G)
  Eigen::Vector3d b = Eigen::Vector3d::Zero();   // magnetic field, microtesla
  Eigen::Vector3d w = Eigen::Vector3d::Zero();   // angular rate, rad/s
  double temp_c = 0;                             // degC
  double depth_m = 0;                            // measured depth along the hole (flags::kHasDepth)
  std::uint32_t flags = 0;
};

// What the simulator knows to be true at one instant.
struct TruthSample {
  double t = 0;
  double inclination_deg = 0;
  double azimuth_deg = 0;
  double toolface_deg = 0;
  double rpm = 0;
  // Drilling runs: position from the collar (NED, m), velocity (m/s) and measured depth (m).
  bool has_position = false;
  double north_m = 0, east_m = 0, down_m = 0;
  double vn_mps = 0, ve_mps = 0, vd_mps = 0;
  double depth_m = 0;
};

}  // namespace plumb
