#include "plumb/components/clearance_options.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace plumb::components {

void add_clearance_options(CLI::App& app, ClearanceCliOptions& o, bool offsets_required) {
  auto* offset = app.add_option("--offset", o.offsets,
                                "an offset well (repeat for each): a plumb survey file (true or grid north) or a station "
                                "list CSV (md_m,inclination_deg,azimuth_deg; its first row's north_m,east_m,tvd_m place it)")
                     ->check(CLI::ExistingFile);
  app.add_option("--sidetrack", o.sidetracks,
                 "an offset well that kicks off the reference at its first station (repeat for each): against it "
                 "both wells' uncertainty counts from the kick-off, the reference surveyed again from there through "
                 "its error model, and the common path above is not scanned")
      ->check(CLI::ExistingFile);
  if (offsets_required) offset->required();
  app.add_option("--reference-radius", o.reference_radius_m, "hole radius of the reference well (the one drilled), m")
      ->capture_default_str();
  app.add_option("--offset-radius", o.offset_radius_m, "offset wells' hole radius, m")->capture_default_str();
  app.add_option("--k", o.rule.k, "confidence scaling factor k of the separation rule")->capture_default_str();
  app.add_option("--sigma-pa", o.rule.sigma_pa_m, "projection-ahead uncertainty, m (1 sigma)")->capture_default_str();
  app.add_option("--surface-margin", o.rule.surface_margin_m, "surface margin S_m, m")->capture_default_str();
  app.add_option("--warning", o.levels.warning_sf, "clearance warning below this separation factor")->capture_default_str();
  app.add_option("--alarm", o.levels.alarm_sf, "clearance alarm below this separation factor")->capture_default_str();
}

void check_clearance_options(const ClearanceCliOptions& o) {
  survey::check_rule(o.rule);
  survey::check_levels(o.levels);
  if (!(o.reference_radius_m >= 0 && o.offset_radius_m >= 0)) throw std::invalid_argument("hole radii must be >= 0");
}

std::string clearance_number(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string clearance_well_name(const std::string& path) {
  std::string n = std::filesystem::path(path).filename().string();
  const auto dot = n.find('.');
  return dot == std::string::npos || dot == 0 ? n : n.substr(0, dot);
}

}  // namespace plumb::components
