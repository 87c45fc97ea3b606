#include "estimate_line.hpp"

#include <cmath>
#include <cstdio>

namespace plumb::estimator_component {

namespace {

std::string printf_text(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// Signed angle difference in (-180, 180].
double angle_error(double estimate_deg, double truth_deg) {
  double d = std::fmod(estimate_deg - truth_deg, 360.0);
  if (d > 180) d -= 360;
  if (d <= -180) d += 360;
  return d;
}

}  // namespace

std::string format_angle(double degrees, int decimals) {
  const double scale = std::pow(10.0, decimals);
  double rounded = std::round(degrees * scale) / scale;
  rounded = std::fmod(rounded, 360.0);
  if (rounded < 0) rounded += 360.0;
  if (std::round(rounded * scale) >= 360.0 * scale) rounded = 0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, rounded + 0.0);  // + 0.0: never "-0.000"
  return buf;
}

std::string estimate_line(const Estimate& e, const std::optional<topics::Truth>& truth) {
  char head[96];
  std::snprintf(head, sizeof head, "%-12s t=%8.2f s  ", e.estimator.c_str(), e.t_end);
  std::string line = head;
  if (!e.valid) {
    // The angles of an invalid estimate are whatever the formula gave: not shown, the reason is.
    line += "INVALID: " + (e.reason.empty() ? std::string("no reason given") : e.reason);
    line += "  rpm " + printf_text("%.1f", e.rpm);
    return line;
  }
  line += "inc " + printf_text("%7.4f", e.inclination_deg) + " deg  ";
  line += e.azimuth_valid ? "azi " + format_angle(e.azimuth_deg, 3) + " deg  " : std::string("azi invalid  ");
  line += e.toolface_valid ? "tf " + format_angle(e.gravity_toolface_deg, 2) + " deg  " : std::string("tf invalid  ");
  line += "rpm " + printf_text("%.1f", e.rpm);
  if (!e.reason.empty()) line += "  (" + e.reason + ")";
  if (truth) {
    line += "  | error inc " + printf_text("%+.4f", e.inclination_deg - truth->inclination_deg) + " deg";
    if (e.azimuth_valid) line += "  azi " + printf_text("%+.3f", angle_error(e.azimuth_deg, truth->azimuth_deg)) + " deg";
  }
  return line;
}

}  // namespace plumb::estimator_component
