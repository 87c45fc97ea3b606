#include "plumb/calibration/report.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace plumb::calibration {

void inclination_summary(const Result& r, double& before_deg, double& after_deg) {
  before_deg = after_deg = -1;
  for (const auto& s : r.residuals) {
    before_deg = std::max(before_deg, s.inclination_before_deg);
    after_deg = std::max(after_deg, s.inclination_after_deg);
  }
}

std::string format_report(const Outcome& outcome, const std::string& procedure) {
  std::ostringstream o;
  char buf[256];
  o << "plumb-calibrate report\nprocedure: " << procedure << "\n";
  if (!outcome.ok()) {
    o << "result: FAILED: " << outcome.error << "\nno coefficients were produced.\n";
  } else {
    const Result& r = *outcome.result;
    o << "result: ok\ntool_id: " << r.model.tool_id << "\ncalibration_id: " << r.model.calibration_id << "\n"
      << r.summary << "\n";
    double before = -1, after = -1;
    inclination_summary(r, before, after);
    if (after >= 0) {
      std::snprintf(buf, sizeof buf,
                    "inclination error at the stations (max over stations with a known orientation): "
                    "before %.4f deg, after %.5f deg\n",
                    before, after);
      o << buf;
    }
    o << "calibrated temperature range: " << r.model.temp_min_c << " to " << r.model.temp_max_c
      << " degC (reference " << r.model.reference_temp_c << " degC)\n";
  }
  o << "\nwarnings: " << outcome.warnings.size() << "\n";
  for (const auto& w : outcome.warnings) o << "  " << w << "\n";
  if (!outcome.ok()) return o.str();
  const Result& r = *outcome.result;
  o << "\nparameters (value, standard deviation):\n";
  for (const auto& p : r.parameters) {
    std::snprintf(buf, sizeof buf, "  %-28s % .10e  %.3e %s\n", p.name.c_str(), p.value, p.sd, p.unit.c_str());
    o << buf;
  }
  o << "\nstations: name, |f| - g (or |B| - B), direction error deg, inclination error before/after deg\n";
  for (const auto& s : r.residuals) {
    std::snprintf(buf, sizeof buf, "  %-20s % .3e  %9.5f  %9.5f  %9.5f\n", s.station.c_str(), s.norm_error,
                  s.direction_error_deg, s.inclination_before_deg, s.inclination_after_deg);
    o << buf;
  }
  std::snprintf(buf, sizeof buf, "residual rms: %.4e\n", r.residual_rms);
  o << buf;
  return o.str();
}

}  // namespace plumb::calibration
