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
  char buf[1024];
  o << "plumb-calibrate report\nprocedure: " << procedure << "\n";
  if (!outcome.ok()) {
    o << "result: FAILED: " << outcome.error << "\nno coefficients were produced.\n";
  } else {
    const Result& r = *outcome.result;
    o << "result: ok\ntool_id: " << r.model.tool_id << "\ncalibration_id: " << r.model.calibration_id << "\n"
      << r.summary << "\n";
    double before = -1, after = -1;
    inclination_summary(r, before, after);
    if (r.predicted.valid) {
      std::snprintf(buf, sizeof buf,
                    "predicted error of this calibration in use (3 sd, from the fit's covariance): inclination "
                    "%.5f deg (worst at inclination %.0f deg, toolface %.0f deg, %.1f degC), azimuth %.5f deg "
                    "(worst at inclination %.0f deg)\n",
                    r.predicted.inclination_deg, r.predicted.inclination_at_deg, r.predicted.toolface_at_deg,
                    r.predicted.temperature_at_c, r.predicted.azimuth_deg, r.predicted.azimuth_at_inclination_deg);
      o << buf << "  over " << r.predicted.grid << "\n  largest contributions at the worst point (3 sd per parameter group):";
      for (const auto& [name, deg] : r.predicted.contributions) {
        std::snprintf(buf, sizeof buf, " %s %.2e deg;", name.c_str(), deg);
        o << buf;
      }
      o << "\n";
    }
    if (after >= 0) {
      std::snprintf(buf, sizeof buf,
                    "inclination error at the stations against their nominal orientations (max): before %.4f deg, "
                    "after %.5f deg\n",
                    before, after);
      o << buf;
    }
    if (r.split.valid) {
      std::snprintf(buf, sizeof buf,
                    "  of which the sensors' errors (what the model leaves at the faces, rotations averaged): "
                    "%.5f deg\n  and the stations' orientations (table top tilt, misplaced stations; turns with "
                    "the turntable and cancels in the rotation average): %.5f deg%s%s\n",
                    r.split.sensor_deg, r.split.orientation_deg,
                    r.split.worst_station.empty() ? "" : ", largest at station ", r.split.worst_station.c_str());
      o << buf;
    }
    for (const auto& d : r.dropped) o << "dropped: " << d << "\n";
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
