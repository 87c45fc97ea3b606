// One readable line per drilling scenario, for the logs of the components.
#include <sstream>

#include "plumb/sim/drilling.hpp"

namespace plumb::sim {

std::string describe(const DrillingScenario& s) {
  const DrillingTrajectory trajectory(s.plan);
  std::size_t drills = 0, rotary = 0;
  for (const auto& seg : s.plan.segments)
    if (seg.kind == SegmentKind::Drill) {
      ++drills;
      if (seg.mode == SteeringMode::Rotary) ++rotary;
    }
  std::ostringstream out;
  out.precision(6);
  out << "drilling run '" << s.tool_id << "': " << trajectory.duration_s() << " s at " << s.sample_rate_hz << " Hz; "
      << s.plan.alignment_s << " s alignment, " << drills << " drilling segment(s) (" << rotary << " rotary) over "
      << trajectory.drilled_length_m() << " m, " << trajectory.stop_count() << " stop(s); start I "
      << s.plan.inclination_deg << " deg, A " << s.plan.azimuth_deg << " deg, T " << s.plan.toolface_deg << " deg; "
      << describe(s.grade) << "; latitude " << s.latitude_deg << " deg, g " << s.g << " m/s2, B " << s.total_b
      << " uT, dip " << s.dip_deg << " deg; ";
  if (s.magnetometer.present)
    out << "magnetometer noise " << s.magnetometer.sigma_uT << " uT, " << s.magnetometer.disturbances.size()
        << " disturbed stop(s); ";
  else
    out << "no magnetometer; ";
  if (s.depth.present)
    out << "depth noise " << s.depth.sigma_m << " m, step " << s.depth.quantum_m << " m; ";
  else
    out << "no depth; ";
  if (s.vibration.lateral_rms > 0)
    out << "vibration " << describe(s.vibration) << "; ";
  if (s.vibration.shock_rate_hz > 0 && s.vibration.shock_peak != 0)
    out << "shocks " << s.vibration.shock_peak << " m/s2 at " << s.vibration.shock_rate_hz << " /s; ";
  if (s.temperature.enabled)
    out << "tool temperature " << s.temperature.circulating_c << " degC circulating, " << s.temperature.formation_c
        << " degC at stops (tau " << s.temperature.cool_tau_s << " / " << s.temperature.heat_tau_s << " s); ";
  out << "seed " << s.seed;
  return out.str();
}

}  // namespace plumb::sim
