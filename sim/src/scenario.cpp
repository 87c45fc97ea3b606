// Scenario defaults, the source paper's reference case and the SNR-to-sigma conversion of shared
// docs/conventions.md "Noise and signal-to-noise ratio".
#include <cmath>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/platform.hpp"

namespace plumb::sim {
namespace {

// sigma such that 10 log10(power / sigma^2) = snr_db.
double sigma_from_snr(double signal_power, double snr_db) {
  return std::sqrt(signal_power / std::pow(10.0, snr_db / 10.0));
}

}  // namespace

Scenario Scenario::reference(double inclination_deg, double azimuth_deg, double rpm, double snr_accel_db,
                             std::uint64_t seed) {
  Scenario s;
  s.tool_id = "reference";
  s.g = 10.0;
  s.total_b = 48.4;
  s.dip_deg = 45.5;
  s.inclination_deg = inclination_deg;
  s.azimuth_deg = azimuth_deg;
  s.rotation.kind = ProfileKind::Constant;
  s.rotation.rpm = rpm;
  s.sample_rate_hz = 100;
  s.duration_s = 10;
  s.noise.snr_accel_db = snr_accel_db;
  s.noise.snr_mag_db = 20.0;
  s.seed = seed;
  return s;
}

double Scenario::sigma_accel() const {
  if (noise.sigma_accel) return *noise.sigma_accel;
  if (!noise.snr_accel_db) return 0.0;
  // Power of the rotating radial component g sinI cos(T): (g sinI)^2 / 2.
  const double radial = g * std::sin(inclination_deg * kDeg);
  return sigma_from_snr(radial * radial / 2.0, *noise.snr_accel_db);
}

double Scenario::sigma_mag() const {
  if (noise.sigma_mag) return *noise.sigma_mag;
  if (!noise.snr_mag_db) return 0.0;
  // Bx^2 + By^2 does not depend on the toolface: evaluate it at T = 0.
  const Eigen::Vector3d b = field_tool(inclination_deg * kDeg, azimuth_deg * kDeg, 0.0, total_b, dip_deg * kDeg);
  return sigma_from_snr((b.x() * b.x() + b.y() * b.y()) / 2.0, *noise.snr_mag_db);
}

double Scenario::temperature_at(double t) const {
  if (duration_s <= 0 || t >= duration_s) return temp_end_c;
  if (t <= 0) return temp_start_c;
  return temp_start_c + (temp_end_c - temp_start_c) * t / duration_s;
}

}  // namespace plumb::sim
