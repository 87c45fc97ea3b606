// The data behind plumb compare's plots, as CSV for plumb-plot (matplotlib): the mean errors per
// azimuth of every case and plugin, and the navigator's errors over time on the drilling runs.
#include <cstdio>

#include "plumb/compare/compare.hpp"
#include "plumb/compare/drilling.hpp"

namespace plumb::compare {

void write_azimuth_points_csv(std::ostream& out, const CompareResult& result) {
  out << "inclination_deg,rpm,snr_accel_db,plugin,azimuth_deg,valid,records,mean_azimuth_error_deg,"
         "mean_inclination_error_deg,crb_azimuth_deg,crb_inclination_deg\n";
  char line[320];
  for (const auto& c : result.cases)
    for (const auto& p : c.plugins)
      for (const auto& a : p.by_azimuth) {
        std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%s,%.17g,%d,%d,%.9g,%.9g,%.9g,%.9g\n", c.inclination_deg,
                      c.rpm, c.snr_accel_db, p.plugin.c_str(), a.azimuth_deg, a.valid, a.records,
                      a.mean_azimuth_error_deg, a.mean_inclination_error_deg, c.crb_azimuth_deg, c.crb_inclination_deg);
        out << line;
      }
}

void write_drilling_errors_csv(std::ostream& out, const std::vector<DrillingRunResult>& runs) {
  out << "run,t,inclination_deg,azimuth_deg,toolface_deg,north_m,east_m,down_m\n";
  char line[320];
  for (const auto& r : runs) {
    char name[96];
    std::snprintf(name, sizeof name, "%s %g Hz %s seed %llu", r.grade.c_str(), r.rate_hz,
                  family_label(r.family), static_cast<unsigned long long>(r.seed));
    for (const auto& p : r.errors) {
      std::snprintf(line, sizeof line, "%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", name, p.t, p.inclination_deg,
                    p.azimuth_deg, p.toolface_deg, p.north_m, p.east_m, p.down_m);
      out << line;
    }
  }
}

}  // namespace plumb::compare
