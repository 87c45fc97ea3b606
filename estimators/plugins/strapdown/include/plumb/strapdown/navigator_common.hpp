// What the navigator's parts (navigator.hpp) share: the reading they are handed, the counters they
// bump, the floors that keep a perfect simulated sensor from making them divide by zero, and the
// small helpers their messages and rows use.
#pragma once

#include <cstdint>
#include <map>
#include <numbers>
#include <optional>
#include <string>

#include <Eigen/Core>

namespace plumb::strapdown {

// A sample that passed the input checks.
struct InputReading {
  double t = 0;
  Eigen::Vector3d f, w;
  std::optional<Eigen::Vector3d> b;
  double b_norm = 0;  // |b|, when there is b
  std::optional<double> depth;
  std::optional<double> temp_c;  // the tool's temperature (degC), when the sample carries it
  bool gyro_bad = false;  // saturated: the rate is the last good one
  bool accel_bad = false;
  // Axes read at or beyond the sensor's range: bits 0-2 the accelerometers x, y, z, bits 3-5 the
  // gyros (a byte: every reading is copied through the lag queue).
  std::uint8_t clipped = 0;
};
inline constexpr std::uint8_t kAxialGyroClipped = 32u;  // InputReading::clipped's bit of the gyro about the tool axis

// The reference field (|B|, dip) the detector and the magnetic updates are gated by: given, or
// learnt at alignment.
struct FieldReference {
  std::optional<double> total_uT, dip;
};

// The navigator's counters by name (navigator.hpp lists them); each part bumps its own.
using Counters = std::map<std::string, std::uint64_t>;
inline void count(Counters& counters, const char* name, std::uint64_t n = 1) { counters[name] += n; }

inline constexpr double kRadToDeg = 180.0 / std::numbers::pi;
inline constexpr double kRadPerSecToDegPerHour = kRadToDeg * 3600.0;
// Noise floors: a perfect simulated sensor must not make the detector or the filter divide by 0.
inline constexpr double kMinSigmaAccel = 1e-3;    // m/s^2 per sample
inline constexpr double kMinSigmaGyro = 1e-6;     // rad/s per sample
inline constexpr double kMinMeanSdGyro = 1e-9;    // rad/s, a zero-rate update's mean
inline constexpr double kMinMeanSdAccel = 1e-6;   // m/s^2, a tilt update's mean

// A step longer than this many nominal intervals has lost samples (one lost sample doubles it).
inline constexpr double kDropoutFactor = 1.5;
// ... and longer than the nominal by this many times the intervals' own spread (a logger's clock
// that jitters by a millisecond at 400 Hz spreads them by 35 %).
inline constexpr double kJitterSigmas = 5.0;

// A still tool stays still across a gap up to this long (s): a logger's dropout, not a new run.
inline constexpr double kStillAcrossGapS = 5.0;

// A rig reports depth about once a second: a held value is at most this old while the tool moves (s).
inline constexpr double kHeldDepthAgeS = 2.0;

// printf-style text of up to three numbers, for notices, warnings and reasons.
std::string format(const char* fmt, double a, double b = 0, double c = 0);

// sin(dip) = G.B / (|G||B|) with G = -f at rest (docs/conventions.md).
double dip_of(const Eigen::Vector3d& f, const Eigen::Vector3d& b);

}  // namespace plumb::strapdown
