// The drilling comparison as a table, beside the source's figures.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plumb/compare/drilling.hpp"

namespace plumb::compare {
namespace {

// What each depth family in the table fed the navigator, and how noisy the sensors were.
void write_families(std::ostream& out, const std::vector<DrillingRunResult>& runs, const DrillingCompareConfig& c) {
  char line[512];
  const auto present = [&](DepthFamily f) {
    return std::any_of(runs.begin(), runs.end(), [f](const DrillingRunResult& r) { return r.family == f; });
  };
  if (present(DepthFamily::sensor) && c.depth_sd_m > 0) {
    std::snprintf(line, sizeof line, "depth yes: a depth sensor on every row with %.3g m of noise (the navigator is not told).\n",
                  c.depth_sd_m);
    out << line;
  }
  if (present(DepthFamily::rig)) {
    std::snprintf(line, sizeof line,
                  "depth rig: a report every %g s, %.3g m of noise (not told), rounded to %.5g m, %g s late, %s between reports.\n",
                  c.rig.interval_s, c.depth_sd_m, c.rig.quantum_m, c.rig.late_s, c.rig.empty_between ? "empty" : "held");
    out << line;
  }
  if (present(DepthFamily::tally)) {
    std::snprintf(line, sizeof line,
                  "depth tally: no depth sensor; the navigator is given each joint's length measured to %.3g m "
                  "(pipe_tally_m, pipe_tally_sd_m).\n",
                  c.tally_sd_m);
    out << line;
  }
  if (c.noisier != 1) {
    std::snprintf(line, sizeof line,
                  "Gyro and accelerometer noise %gx their grade's preset; the navigator is told only the grade.\n", c.noisier);
    out << line;
  }
}

// One row per estimator, grade, rate and depth family over its seeds: the worst errors, and the
// coverage pooled over every ratio of every run (attitude) and over the runs' last rows (end position).
void write_family_summary(std::ostream& out, const std::vector<DrillingRunResult>& runs, const std::string& plugin) {
  std::vector<std::vector<const DrillingRunResult*>> groups;
  for (const auto& r : runs) {
    auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& members) {
      const auto& m = *members.front();
      return m.grade == r.grade && m.rate_hz == r.rate_hz && m.family == r.family;
    });
    if (g == groups.end()) groups.push_back({&r});
    else g->push_back(&r);
  }
  if (std::none_of(groups.begin(), groups.end(), [](const auto& members) { return members.size() > 1; })) return;
  char line[512];
  out << "\nPer depth family, over its seeds: the worst errors; c.att and c.end pooled over the runs.\n";
  std::snprintf(line, sizeof line, "%-10s %-9s %6s %5s %4s | %8s %8s %8s %8s | %8s %6s | %5s %5s | %s\n", "estimator", "grade",
                "Hz", "depth", "runs", "max att", "max inc", "max azi", "max tf", "end pos", "%", "c.att", "c.end",
                "fewest valid");
  out << line;
  for (const auto& members : groups) {
    double att = 0, inc = 0, azi = 0, tf = 0, end_m = 0, end_pct = 0, att_z2 = 0, att_n = 0, end_z2 = 0;
    int fewest_valid = members.front()->valid;
    for (const DrillingRunResult* r : members) {
      att = std::max(att, r->max_attitude_deg), inc = std::max(inc, r->max_inclination_deg);
      azi = std::max(azi, r->max_azimuth_deg), tf = std::max(tf, r->max_toolface_deg);
      end_m = std::max(end_m, r->end_position_m), end_pct = std::max(end_pct, r->end_position_percent());
      att_z2 += r->attitude_coverage * r->attitude_coverage * r->attitude_ratios, att_n += r->attitude_ratios;
      end_z2 += r->end_position_coverage * r->end_position_coverage;
      fewest_valid = std::min(fewest_valid, r->valid);
    }
    const auto& first = *members.front();
    std::snprintf(line, sizeof line, "%-10s %-9s %6.0f %5s %4zu | %8.3f %8.3f %8.3f %8.3f | %8.3f %6.2f | %5.2f %5.2f | %d/%d\n",
                  plugin.c_str(), first.grade.c_str(), first.rate_hz, family_name(first.family), members.size(), att, inc,
                  azi, tf, end_m, end_pct, att_n > 0 ? std::sqrt(att_z2 / att_n) : 0.0,
                  std::sqrt(end_z2 / static_cast<double>(members.size())), fewest_valid, first.estimates);
    out << line;
  }
}

}  // namespace

void write_drilling_report(std::ostream& out, const std::vector<DrillingRunResult>& runs, const DrillingCompareConfig& config) {
  char line[512];
  out << "Drilling runs (16 min, four 60 s pipe connections, inclination 85-89 deg) through the navigator ("
      << config.plugin << ").\n"
         "Errors against the exact trajectory; the source reports attitude within "
      << kSourceAttitudeDeg << " deg, north/east velocity within " << kSourceHorizontalVelocityMps
      << " m/s, down within " << kSourceDownVelocityMps << " m/s over 15 min.\n"
         "coverage = RMS(error / reported sd): 1 when the reported sd is honest (c.inc, c.azi, c.tf per angle,\n"
         "c.att pooled over the three, c.pos over north, east, down on every row, c.end at the last row).\n";
  write_families(out, runs, config);
  out << '\n';
  std::snprintf(line, sizeof line, "%-9s %6s %5s %4s | %8s %8s %8s %8s | %8s %8s %6s | %8s %8s | %5s %5s %5s %5s %5s %5s | %s\n",
                "grade", "Hz", "depth", "seed", "max att", "rms inc", "rms azi", "rms tf", "end pos", "drilled", "%",
                "max vNE", "max vD", "c.inc", "c.azi", "c.tf", "c.att", "c.pos", "c.end", "valid");
  out << line;
  std::snprintf(line, sizeof line, "%-9s %6s %5s %4s | %8s %8s %8s %8s | %8s %8s %6s | %8s %8s | %5s %5s %5s %5s %5s %5s |\n",
                "", "", "", "", "deg", "deg", "deg", "deg", "m", "m", "", "m/s", "m/s", "", "", "", "", "", "");
  out << line;
  for (const auto& r : runs) {
    std::snprintf(line, sizeof line,
                  "%-9s %6.0f %5s %4llu | %8.3f %8.3f %8.3f %8.3f | %8.3f %8.2f %6.2f | %8.4f %8.4f | %5.2f %5.2f %5.2f %5.2f %5.2f %5.2f | "
                  "%d/%d\n",
                  r.grade.c_str(), r.rate_hz, family_name(r.family), static_cast<unsigned long long>(r.seed),
                  r.max_attitude_deg, r.rms_inclination_deg, r.rms_azimuth_deg, r.rms_toolface_deg, r.end_position_m,
                  r.drilled_m, r.end_position_percent(), r.max_horizontal_velocity_mps, r.max_down_velocity_mps,
                  r.inclination_coverage, r.azimuth_coverage, r.toolface_coverage, r.attitude_coverage,
                  r.position_coverage, r.end_position_coverage, r.valid, r.estimates);
    out << line;
    if (r.valid == 0 && !r.first_invalid_reason.empty()) out << "  no valid estimate: " << r.first_invalid_reason << '\n';
  }
  write_family_summary(out, runs, config.plugin);
  if (!runs.empty()) {
    double worst = 0;
    for (const auto& r : runs) worst = std::max(worst, r.max_attitude_deg);
    std::snprintf(line, sizeof line, "\nWorst attitude error %.3f deg: %.0fx better than the source's %.0f deg.\n", worst,
                  worst > 0 ? kSourceAttitudeDeg / worst : 0.0, kSourceAttitudeDeg);
    out << line;
  }
}

}  // namespace plumb::compare
