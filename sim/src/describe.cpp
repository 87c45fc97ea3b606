// Readable one-line summaries of a profile and a scenario, for the logs of the components.
#include <sstream>

#include "plumb/sim/platform.hpp"

namespace plumb::sim {
namespace {

bool any(const TriadErrors& e) {
  return !e.bias.isZero(0) || !e.scale.isZero(0) || !e.misalignment.isZero(0) || !e.bias_temp.isZero(0);
}

}  // namespace

std::string describe(const RotationProfile& p) {
  std::ostringstream out;
  switch (p.kind) {
    case ProfileKind::Constant:
      out << p.rpm << " rpm";
      break;
    case ProfileKind::Ramp:
      out << "ramp " << p.rpm << " to " << p.rpm_end << " rpm over " << p.ramp_s << " s";
      break;
    case ProfileKind::StopAndGo:
      out << "stop-and-go, mean " << p.rpm << " rpm, period " << p.period_s << " s";
      break;
    case ProfileKind::StickSlip:
      out << "stick-slip, mean " << p.rpm << " rpm, period " << p.period_s << " s";
      break;
  }
  return out.str();
}

std::string describe(const Scenario& s) {
  std::ostringstream out;
  out.precision(6);
  out << "tool '" << s.tool_id << "': I " << s.inclination_deg << " deg, A " << s.azimuth_deg << " deg, T0 "
      << s.toolface0_deg << " deg, " << describe(s.rotation) << "; g " << s.g << " m/s2, B " << s.total_b
      << " uT, dip " << s.dip_deg << " deg; " << s.sample_rate_hz << " Hz, " << s.duration_s << " s; noise sigma "
      << s.sigma_accel() << " m/s2, " << s.sigma_mag() << " uT";
  if (s.with_gyro) out << ", " << s.noise.sigma_gyro << " rad/s";
  if (s.vibration.lateral_rms > 0) out << "; vibration " << describe(s.vibration);
  if (s.vibration.shock_rate_hz > 0 && s.vibration.shock_peak != 0)
    out << "; shocks " << s.vibration.shock_peak << " m/s2 at " << s.vibration.shock_rate_hz << " /s";
  if (any(s.accel_errors) || any(s.mag_errors) || any(s.gyro_errors)) out << "; sensor errors on";
  if (s.temp_start_c != s.temp_end_c)
    out << "; temperature " << s.temp_start_c << " to " << s.temp_end_c << " C";
  else
    out << "; temperature " << s.temp_start_c << " C";
  out << "; seed " << s.seed;
  return out.str();
}

}  // namespace plumb::sim
