// One readable line per walk, for the logs of the components.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "plumb/sim/walk.hpp"

namespace plumb::sim {

std::string describe(const WalkScenario& s) {
  const WalkPath path(s);
  double climb = 0, height = 0;
  for (const auto& leg : s.legs) {
    height += leg.climb_m;
    climb = std::max(climb, height);
  }
  std::ostringstream out;
  out.precision(6);
  out << "walk '" << s.tool_id << "' (IMU on a foot, tool z forward, x up): " << path.duration_s() << " s at "
      << s.sample_rate_hz << " Hz; closed loop of " << path.horizontal_length_m() << " m (" << path.length_m()
      << " m in 3-D, up to " << climb << " m of stairs), " << path.swings().size() << " strides at "
      << s.cadence_hz << " /s, stance " << s.stance_min_s << ".." << s.stance_max_s << " s, first heading "
      << s.heading_deg << " deg; still " << s.initial_still_s << " s before, " << s.final_still_s << " s after; "
      << describe(s.grade) << "; latitude " << s.latitude_deg << " deg, g " << s.g << " m/s2, B " << s.total_b
      << " uT, dip " << s.dip_deg << " deg; ";
  if (s.magnetometer)
    out << "magnetometer noise " << s.mag_sigma_uT << " uT; ";
  else
    out << "no magnetometer; ";
  out << "seed " << s.seed;
  return out.str();
}

}  // namespace plumb::sim
