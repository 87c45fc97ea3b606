// plumb clearance: anti-collision offline. The reference well (the one being drilled) against each
// offset well, station by station, by the ISCWSA separation rule (docs/surveys.md,
// "Anti-collision"): per reference station the nearest offset, centre-to-centre distance, ellipse
// separation, separation factor and its level; every pair optionally as CSV.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "plumb/components/clearance_options.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/survey/clearance.hpp"
#include "plumb/survey/clearance_well_file.hpp"
#include "plumb/survey/survey_file.hpp"
#include "plots/plot_runner.hpp"
#include "verbs.hpp"

namespace plumb::cli {
namespace {

struct ClearanceCommandOptions {
  std::string reference;
  components::ClearanceCliOptions clearance;
  survey::StationListModel model;
  std::string first_station = "surveyed";
  std::string csv, plot;
};

std::string clearance_csv_header() {
  return "reference_md_m,reference_north_m,reference_east_m,reference_tvd_m,offset,offset_md_m,offset_north_m,"
         "offset_east_m,offset_tvd_m,centre_to_centre_m,horizontal_bearing_deg,high_side_bearing_deg,"
         "reference_sigma_m,offset_sigma_m,sigma_s_m,masd_m,ellipse_separation_m,separation_factor,level,warning_sf,"
         "alarm_sf,reference_cov_nn,reference_cov_ne,reference_cov_ee,offset_cov_nn,offset_cov_ne,offset_cov_ee\n";
}

std::string clearance_csv_row(const survey::StationClearance& c, const std::string& offset, const survey::ClearanceLevels& l) {
  std::ostringstream o;
  o.precision(10);
  o << c.reference.md_m << ',' << c.reference.position.x() << ',' << c.reference.position.y() << ','
    << c.reference.position.z() << ',' << offset << ',' << c.offset.md_m << ',' << c.offset.position.x() << ','
    << c.offset.position.y() << ',' << c.offset.position.z() << ',' << c.centre_to_centre_m << ','
    << c.horizontal_bearing_deg << ',' << c.high_side_bearing_deg << ',' << c.reference_sigma_m << ','
    << c.offset_sigma_m << ',' << c.sigma_s_m << ',' << c.masd_m << ',' << c.ellipse_separation_m << ','
    << c.separation_factor << ',' << survey::to_string(survey::clearance_level(c.separation_factor, l)) << ','
    << l.warning_sf << ',' << l.alarm_sf;
  // Each well's horizontal covariance there (north, east; m^2): the plan's ellipses.
  for (const Eigen::Matrix3d* p : {&c.reference.covariance, &c.offset.covariance})
    o << ',' << (*p)(0, 0) << ',' << (*p)(0, 1) << ',' << (*p)(1, 1);
  o << '\n';
  return o.str();
}

int run_clearance(ClearanceCommandOptions o) {
  components::check_clearance_options(o.clearance);
  const auto& rule = o.clearance.rule;
  const auto& levels = o.clearance.levels;
  o.model.first_station_surveyed = o.first_station == "surveyed";
  if (o.clearance.offsets.empty() && o.clearance.sidetracks.empty())
    throw std::invalid_argument("no offset well: give --offset FILE or --sidetrack FILE (each may be repeated)");
  const std::string reference_name = components::clearance_well_name(o.reference);
  const auto reference = survey::read_clearance_well(o.reference, reference_name, o.clearance.reference_radius_m, o.model);
  // A sidetrack shares the reference's path down to its kick-off (its first station): against it,
  // the reference counts its uncertainty from there too, and the path above is not scanned.
  struct Offset {
    survey::ClearanceWellFile file;
    std::optional<survey::ClearanceWell> reference_below;
  };
  std::vector<Offset> offsets;
  const auto add_offset = [&](const std::string& path, bool sidetrack) {
    Offset off{survey::read_clearance_well(path, components::clearance_well_name(path), o.clearance.offset_radius_m, o.model),
               std::nullopt};
    std::string said = "plumb clearance: " + off.file.well.name + ": " + std::to_string(off.file.well.stations.size()) +
                       " station(s), error model " + off.file.error_model;
    if (sidetrack) {
      const double kick_off = off.file.well.stations.front().md_m;
      off.reference_below = survey::read_clearance_well_below(o.reference, reference_name,
                                                              o.clearance.reference_radius_m, o.model, kick_off)
                                .well;
      said += "; a sidetrack of " + reference_name + " from MD " + components::clearance_number(kick_off, 2) +
              " m (both wells' uncertainty from there)";
    }
    std::cerr << said << '\n';
    offsets.push_back(std::move(off));
  };
  for (const auto& path : o.clearance.offsets) add_offset(path, false);
  for (const auto& path : o.clearance.sidetracks) add_offset(path, true);
  std::string table = clearance_csv_header();
  std::cout << "# reference " << reference.well.name << " (" << reference.well.stations.size() << " stations, error model "
            << reference.error_model << "); k " << rule.k << ", sigma_pa " << rule.sigma_pa_m << " m, S_m "
            << rule.surface_margin_m << " m; warning SF < " << levels.warning_sf << ", alarm SF < " << levels.alarm_sf
            << '\n';
  std::cout << "reference_md_m  nearest_offset  offset_md_m  centre_to_centre_m  ellipse_separation_m  separation_factor  level\n";
  double min_sf = std::numeric_limits<double>::infinity();
  std::string min_where;
  int warnings = 0, alarms = 0, scanned = 0;
  for (const auto& station : reference.well.stations) {
    // The offset this station is least clear of: the smallest separation factor.
    survey::StationClearance worst;
    std::string worst_name;
    for (const auto& off : offsets) {
      const survey::WellPoint* seen_from = &station;
      if (off.reference_below) {
        const auto& below = off.reference_below->stations;
        const auto same = std::find_if(below.begin(), below.end(), [&](const auto& p) { return p.md_m == station.md_m; });
        if (same == below.end()) continue;  // above the kick-off: the wells' common path
        seen_from = &*same;
      }
      const auto c = survey::station_clearance(*seen_from, reference.well.radius_m, off.file.well, rule);
      table += clearance_csv_row(c, off.file.well.name, levels);
      if (worst_name.empty() || c.separation_factor < worst.separation_factor) {
        worst = c;
        worst_name = off.file.well.name;
      }
    }
    if (worst_name.empty()) continue;
    ++scanned;
    const auto level = survey::clearance_level(worst.separation_factor, levels);
    warnings += level == survey::ClearanceLevel::Warning;
    alarms += level == survey::ClearanceLevel::Alarm;
    if (worst.separation_factor < min_sf) {
      min_sf = worst.separation_factor;
      min_where = worst_name + " at reference MD " + components::clearance_number(station.md_m, 2) + " m";
    }
    std::cout << components::clearance_number(station.md_m, 2) << "  " << worst_name << "  " << components::clearance_number(worst.offset.md_m, 2)
              << "  " << components::clearance_number(worst.centre_to_centre_m, 3) << "  "
              << components::clearance_number(worst.ellipse_separation_m, 3) << "  " << components::clearance_number(worst.separation_factor, 3)
              << "  " << survey::to_string(level) << '\n';
  }
  if (!o.csv.empty()) survey::write_file_atomically(o.csv, table);
  if (!o.plot.empty()) {
    // Drawn from the CSV; without --csv, from a copy beside the plot.
    const std::string csv = o.csv.empty() ? o.plot + ".clearance.csv" : o.csv;
    if (o.csv.empty()) survey::write_file_atomically(csv, table);
    run_plot("clearance", csv, o.plot);
    if (o.csv.empty()) std::filesystem::remove(csv);
  }
  std::cerr << "plumb clearance: " << scanned << " reference station(s) against "
            << offsets.size() << " offset well(s): smallest SF " << components::clearance_number(min_sf, 3) << " (" << min_where
            << "); " << warnings << " station(s) at warning, " << alarms << " at alarm\n";
  return 0;
}

}  // namespace

void add_clearance_verb(CLI::App& app, Verbs& verbs) {
  auto o = std::make_shared<ClearanceCommandOptions>();
  auto* cmd = app.add_subcommand("clearance", "Anti-collision offline: the reference well against offset wells by the "
                                              "ISCWSA separation rule (docs/surveys.md)");
  cmd->add_option("-r,--reference", o->reference, "the reference well: a plumb survey file (true or grid north) or a "
                                                  "station list CSV (md_m,inclination_deg,azimuth_deg; its first row's "
                                                  "north_m,east_m,tvd_m place it)")
      ->required()
      ->check(CLI::ExistingFile);
  components::add_clearance_options(*cmd, o->clearance, /*offsets_required=*/false);
  cmd->add_option("--error-model", o->model.error_model, "error model of station-list wells: a built-in tool code "
                                                         "(MWD, MWD:rev4, ...) or a tool code file")
      ->capture_default_str();
  cmd->add_option("--gravity", o->model.gravity_mps2, "reference gravity for station-list wells, m/s^2")->capture_default_str();
  cmd->add_option("--total-field", o->model.total_b_uT, "reference total field for station-list wells, uT")
      ->capture_default_str();
  cmd->add_option("--dip", o->model.dip_deg, "reference dip for station-list wells, deg")->capture_default_str();
  cmd->add_option("--latitude", o->model.latitude_deg, "latitude, deg (gyro error models)");
  cmd->add_option("--first-station", o->first_station, "a station list's first station: surveyed (its errors tilt "
                                                      "the course below it) or tie-in (no error of its own)")
      ->check(CLI::IsMember({"surveyed", "tie-in"}))
      ->capture_default_str();
  cmd->add_option("--csv", o->csv, "write every reference station against every offset as CSV (written whole or not at all)");
  cmd->add_option("--plot", o->plot, "draw the travelling cylinder, the plan view and the separation factor along the "
                                     "reference well (with plumb-plot and python3-matplotlib): .png, .svg or .pdf");
  verbs.add(cmd, [o] { return run_clearance(*o); });
}

}  // namespace plumb::cli
