// The drilling comparison as a table, beside the source's figures.
#include <cstdio>

#include "plumb/compare/drilling.hpp"

namespace plumb::compare {

void write_drilling_report(std::ostream& out, const std::vector<DrillingRunResult>& runs) {
  char line[512];
  out << "Drilling runs (16 min, four 60 s pipe connections, inclination 85-89 deg) through the navigator.\n"
         "Errors against the exact trajectory; the source reports attitude within "
      << kSourceAttitudeDeg << " deg, north/east velocity within " << kSourceHorizontalVelocityMps
      << " m/s, down within " << kSourceDownVelocityMps << " m/s over 15 min.\n"
         "coverage = RMS(error / reported sd): 1 when the reported sd is honest (c.inc, c.azi, c.tf per angle,\n"
         "c.att pooled over the three, c.pos over north, east, down).\n\n";
  std::snprintf(line, sizeof line, "%-9s %6s %5s %4s | %8s %8s %8s %8s | %8s %8s %6s | %8s %8s | %5s %5s %5s %5s %5s | %s\n",
                "grade", "Hz", "depth", "seed", "max att", "rms inc", "rms azi", "rms tf", "end pos", "drilled", "%",
                "max vNE", "max vD", "c.inc", "c.azi", "c.tf", "c.att", "c.pos", "valid");
  out << line;
  std::snprintf(line, sizeof line, "%-9s %6s %5s %4s | %8s %8s %8s %8s | %8s %8s %6s | %8s %8s | %5s %5s %5s %5s %5s |\n",
                "", "", "", "", "deg", "deg", "deg", "deg", "m", "m", "", "m/s", "m/s", "", "", "", "", "");
  out << line;
  for (const auto& r : runs) {
    std::snprintf(line, sizeof line,
                  "%-9s %6.0f %5s %4llu | %8.3f %8.3f %8.3f %8.3f | %8.3f %8.2f %6.2f | %8.4f %8.4f | %5.2f %5.2f %5.2f %5.2f %5.2f | "
                  "%d/%d\n",
                  r.grade.c_str(), r.rate_hz, r.with_depth ? "yes" : "no", static_cast<unsigned long long>(r.seed),
                  r.max_attitude_deg, r.rms_inclination_deg, r.rms_azimuth_deg, r.rms_toolface_deg, r.end_position_m,
                  r.drilled_m, r.end_position_percent(), r.max_horizontal_velocity_mps, r.max_down_velocity_mps,
                  r.inclination_coverage, r.azimuth_coverage, r.toolface_coverage, r.attitude_coverage,
                  r.position_coverage, r.valid, r.estimates);
    out << line;
    if (r.valid == 0 && !r.first_invalid_reason.empty()) out << "  no valid estimate: " << r.first_invalid_reason << '\n';
  }
  if (!runs.empty()) {
    double worst = 0;
    for (const auto& r : runs) worst = std::max(worst, r.max_attitude_deg);
    std::snprintf(line, sizeof line, "\nWorst attitude error %.3f deg: %.0fx better than the source's %.0f deg.\n", worst,
                  worst > 0 ? kSourceAttitudeDeg / worst : 0.0, kSourceAttitudeDeg);
    out << line;
  }
}

}  // namespace plumb::compare
