#include "clearance_watch.hpp"

#include <stdexcept>
#include <utility>

namespace plumb::survey_component {
namespace {

using components::clearance_number;

std::string describe(const ClearanceWatch::Pair& p, const survey::ClearanceLevels& levels) {
  const auto& c = p.clearance;
  std::string line = "clearance " + survey::to_string(p.level) + " at MD " + clearance_number(c.reference.md_m, 2) + " m: SF " +
                     clearance_number(c.separation_factor, 2) + " against " + p.offset + " (its MD " + clearance_number(c.offset.md_m, 1) +
                     " m, " + clearance_number(c.centre_to_centre_m, 2) + " m centre to centre, ellipse separation " +
                     clearance_number(c.ellipse_separation_m, 2) + " m)";
  if (p.level == survey::ClearanceLevel::Warning) line += "; warning below SF " + clearance_number(levels.warning_sf, 2);
  if (p.level == survey::ClearanceLevel::Alarm) line += "; alarm below SF " + clearance_number(levels.alarm_sf, 2);
  return line;
}

}  // namespace

void ClearanceWatch::check_sidetracks(const components::ClearanceCliOptions& options, bool survey_has_tool_code) {
  if (!options.sidetracks.empty() && !survey_has_tool_code)
    throw std::invalid_argument("--sidetrack needs an ISCWSA error model for the survey (--error-model MWD, GYRO-NS, "
                                "a tool code file; not plumb): the well drilled is surveyed again from the kick-off "
                                "through it");
}

ClearanceWatch::ClearanceWatch(const components::ClearanceCliOptions& options, const survey::StationListModel& model,
                               const std::optional<survey::StationListModel>& reference_model,
                               survey::AzimuthReference survey_reference, std::function<void(const std::string&)> note)
    : options_(options), reference_model_(reference_model), note_(std::move(note)) {
  if (options_.offsets.empty() && options_.sidetracks.empty()) return;
  components::check_clearance_options(options_);
  if (survey_reference == survey::AzimuthReference::Magnetic)
    throw std::invalid_argument("--offset and --sidetrack need a survey in true or grid north (--reference true or "
                                "grid): a magnetic north moves with the field, and the wells share no frame in it");
  check_sidetracks(options_, reference_model_.has_value());
  const auto read = [&](const std::string& path, bool sidetrack) {
    Offset offset;
    offset.file = survey::read_clearance_well(path, components::clearance_well_name(path), options_.offset_radius_m, model);
    offset.sidetrack = sidetrack;
    const auto& w = offset.file;
    if (sidetrack) offset.view.emplace(w.well.stations.front().md_m, *reference_model_, "the well drilled");
    std::string line = "offset well " + w.well.name + ": " + std::to_string(w.well.stations.size()) + " station(s) from " +
                       path + ", error model " + w.error_model;
    if (sidetrack)
      line += "; a sidetrack of the well drilled from MD " + clearance_number(w.well.stations.front().md_m, 2) +
              " m: scanned below it, both wells' uncertainty from there (the well surveyed again through " +
              reference_model_->error_model + ")";
    note_(line);
    offsets_.push_back(std::move(offset));
  };
  for (const auto& path : options_.offsets) read(path, false);
  for (const auto& path : options_.sidetracks) read(path, true);
  note_("clearance by the ISCWSA separation rule (k " + clearance_number(options_.rule.k, 2) + ", sigma_pa " +
        clearance_number(options_.rule.sigma_pa_m, 2) + " m, S_m " + clearance_number(options_.rule.surface_margin_m, 2) + " m): warning below SF " +
        clearance_number(options_.levels.warning_sf, 2) + ", alarm below " + clearance_number(options_.levels.alarm_sf, 2) + ", on " +
        "plumb/clearance and plumb/status");
}

void ClearanceWatch::start_leg(const survey::iscwsa::ToolCode& tool) {
  for (Offset& offset : offsets_)
    if (offset.view) offset.view->start_leg(tool);
}

std::optional<ClearanceWatch::Pair> ClearanceWatch::sidetrack_pair(Offset& offset, const survey::SurveyRow& row,
                                                                   const survey::WellPoint& station) {
  if (!offset.view) return std::nullopt;
  // As a station list holds it: depth and angles in the survey's north, nothing measured besides but
  // the station's time (a gyro model's continuous terms time the drift by it).
  survey::Station listed;
  listed.md_m = row.station.md_m;
  listed.inclination_deg = row.station.inclination_deg;
  listed.magnetic_azimuth_deg = row.azimuth_deg;
  listed.t_s = row.station.t_s;
  try {
    const auto seen = offset.view->add(listed, station);
    if (!seen) return std::nullopt;  // above the kick-off: the wells' common hole
    Pair p;
    p.offset = offset.file.well.name;
    p.clearance = survey::station_clearance(*seen, options_.reference_radius_m, offset.file.well, options_.rule);
    p.level = survey::clearance_level(p.clearance.separation_factor, options_.levels);
    return p;
  } catch (const std::exception& e) {
    note_("sidetrack " + offset.file.well.name + " is not scanned any more: " + e.what());
    offset.view.reset();
    return std::nullopt;
  }
}

std::vector<ClearanceWatch::Pair> ClearanceWatch::at_station(const survey::SurveyRow& row) {
  std::vector<Pair> pairs;
  if (offsets_.empty()) return pairs;
  // The newest station's covariance is the survey's there: later stations do not change it.
  const survey::WellPoint station = survey::well_point(row);
  pairs.reserve(offsets_.size());
  for (auto& offset : offsets_) {
    if (offset.sidetrack) {
      if (auto p = sidetrack_pair(offset, row, station)) pairs.push_back(std::move(*p));
      continue;
    }
    Pair p;
    p.offset = offset.file.well.name;
    p.clearance = survey::station_clearance(station, options_.reference_radius_m, offset.file.well, options_.rule);
    p.level = survey::clearance_level(p.clearance.separation_factor, options_.levels);
    pairs.push_back(std::move(p));
  }
  if (pairs.empty()) return pairs;  // only sidetracks, and this station above their kick-offs
  const Pair* worst = nullptr;
  for (const auto& p : pairs)
    if (!worst || !(p.clearance.separation_factor >= worst->clearance.separation_factor)) worst = &p;
  ++stations_;
  warning_stations_ += worst->level == survey::ClearanceLevel::Warning;
  alarm_stations_ += worst->level == survey::ClearanceLevel::Alarm;
  const std::string line = describe(*worst, options_.levels);
  if (worst->level != level_) note_(line + (worst->level == survey::ClearanceLevel::Clear ? " (clear again)" : ""));
  level_ = worst->level;
  status_line_ = level_ == survey::ClearanceLevel::Clear ? std::string() : line;
  return pairs;
}

std::vector<std::pair<std::string, std::uint64_t>> ClearanceWatch::counters() const {
  if (offsets_.empty()) return {};
  return {{"clearance_offsets", offsets_.size()},
          {"clearance_level", static_cast<std::uint64_t>(level_)},  // 0 clear, 1 warning, 2 alarm
          {"clearance_warning_stations", warning_stations_},
          {"clearance_alarm_stations", alarm_stations_}};
}

}  // namespace plumb::survey_component
