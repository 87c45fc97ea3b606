// Text and CSV tables of a comparison.
#include <cmath>
#include <cstdio>

#include "plumb/compare/compare.hpp"

namespace plumb::compare {

namespace {

std::string line(const char* fmt, auto... args) {
  char text[512];
  std::snprintf(text, sizeof text, fmt, args...);
  return text;
}

double ratio(double a, double b) { return b > 0 ? a / b : 0.0; }

}  // namespace

void write_report(std::ostream& out, const CompareResult& result) {
  out << line("%6s %5s %5s  %-12s %9s  %8s %8s %8s %6s %6s  %8s %8s %8s %6s %6s  %8s\n", "I_deg", "rpm", "SNRa",
              "plugin", "valid", "az_rms", "az_max", "az_crb", "ratio", "cover", "inc_rms", "inc_max", "inc_crb",
              "ratio", "cover", "az_sinA");
  for (const auto& c : result.cases) {
    for (const auto& p : c.plugins) {
      out << line("%6.2f %5.0f %5.0f  %-12s %4d/%-4d  %8.4f %8.4f %8.4f %6.2f %6.2f  %8.5f %8.5f %8.5f %6.2f %6.2f  %8.4f\n",
                  c.inclination_deg, c.rpm, c.snr_accel_db, p.plugin.c_str(), p.valid, p.records,
                  p.rms_azimuth_error_deg, p.max_azimuth_error_deg, c.crb_azimuth_deg,
                  ratio(p.rms_azimuth_error_deg, c.crb_azimuth_deg), p.azimuth_coverage, p.rms_inclination_error_deg,
                  p.max_inclination_error_deg, c.crb_inclination_deg,
                  ratio(p.rms_inclination_error_deg, c.crb_inclination_deg), p.inclination_coverage, p.bias_sin_deg);
      if (p.valid < p.records && !p.first_invalid_reason.empty()) {
        out << "       " << p.plugin << ": " << (p.records - p.valid) << " invalid, e.g. \"" << p.first_invalid_reason
            << "\"\n";
      }
    }
  }
  out << line("%zu records in %.1f s; errors in degrees; ratio = RMS error / Cramer-Rao bound; cover = RMS(error / "
              "the plugin's reported sd), 1 when honest; az_sinA = fitted amplitude of the azimuth error's sinA term\n",
              result.records, result.seconds);
}

void write_csv(std::ostream& out, const CompareResult& result) {
  out << "inclination_deg,rpm,snr_accel_db,snr_mag_db,sigma_accel,sigma_mag,plugin,valid,records,"
         "azimuth_rms_deg,azimuth_max_deg,azimuth_crb_deg,inclination_rms_deg,inclination_max_deg,"
         "inclination_crb_deg,azimuth_bias_mean_deg,azimuth_bias_sin_deg,azimuth_bias_cos_deg,azimuth_coverage,"
         "inclination_coverage\n";
  for (const auto& c : result.cases) {
    for (const auto& p : c.plugins) {
      out << line("%g,%g,%g,%g,%.6g,%.6g,%s,%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", c.inclination_deg,
                  c.rpm, c.snr_accel_db, c.snr_mag_db, c.sigma_accel, c.sigma_mag, p.plugin.c_str(), p.valid,
                  p.records, p.rms_azimuth_error_deg, p.max_azimuth_error_deg, c.crb_azimuth_deg,
                  p.rms_inclination_error_deg, p.max_inclination_error_deg, c.crb_inclination_deg, p.bias_mean_deg,
                  p.bias_sin_deg, p.bias_cos_deg, p.azimuth_coverage, p.inclination_coverage);
    }
  }
}

}  // namespace plumb::compare
