// plumb-survey's anti-collision: each new station of the well being drilled against every offset
// well (read once, at start) by the ISCWSA separation rule, and the level of the least clear one,
// said when it changes (docs/surveys.md, "Anti-collision"). A sidetrack of the well drilled is
// scanned below its kick-off only, the well surveyed again from there as plumb clearance
// --sidetrack does (survey::SidetrackView, the same code, fed one station at a time).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "plumb/components/clearance_options.hpp"
#include "plumb/survey/clearance_well_file.hpp"
#include "plumb/survey/survey.hpp"

namespace plumb::survey_component {

class ClearanceWatch {
 public:
  struct Pair {
    std::string offset;  // the offset well's name
    survey::StationClearance clearance;
    survey::ClearanceLevel level = survey::ClearanceLevel::Clear;
  };

  // Reads the offset wells (station lists through `model`). `reference_model` is how the survey's
  // own stations are surveyed again from a sidetrack's kick-off (its error model and field); none:
  // the survey has no ISCWSA error model, and a sidetrack is refused. Throws std::invalid_argument
  // for a survey whose north is magnetic (it moves with the field: no common frame with the
  // offsets) and for options that cannot work; std::runtime_error naming the file for an offset it
  // cannot read.
  ClearanceWatch(const components::ClearanceCliOptions& options, const survey::StationListModel& model,
                 const std::optional<survey::StationListModel>& reference_model,
                 survey::AzimuthReference survey_reference, std::function<void(const std::string&)> note);

  // Throws std::invalid_argument for --sidetrack without an ISCWSA error model for the survey
  // (`survey_has_tool_code` false): said before joining the network.
  static void check_sidetracks(const components::ClearanceCliOptions& options, bool survey_has_tool_code);

  bool active() const { return !offsets_.empty(); }
  // The survey's newest station against every offset well (a sidetrack: once below its kick-off).
  // Every row of the survey comes here, in order: a sidetrack's view is built from them.
  std::vector<Pair> at_station(const survey::SurveyRow& row);
  // The survey started a leg (survey::Survey::start_leg): the sidetracks see the well drilled the same way.
  void start_leg(const survey::iscwsa::ToolCode& tool);

  survey::ClearanceLevel level() const { return level_; }
  const survey::ClearanceLevels& levels() const { return options_.levels; }
  // The newest station's least clear pair, in a line; empty while clear or before any station.
  const std::string& status_line() const { return status_line_; }
  std::vector<std::pair<std::string, std::uint64_t>> counters() const;

 private:
  struct Offset {
    survey::ClearanceWellFile file;
    // A sidetrack: the survey's well as it sees it, from its kick-off (its first station); none
    // once it cannot be scanned (said once).
    std::optional<survey::SidetrackView> view;
    bool sidetrack = false;
  };
  std::optional<Pair> sidetrack_pair(Offset& offset, const survey::SurveyRow& row, const survey::WellPoint& station);

  components::ClearanceCliOptions options_;
  std::optional<survey::StationListModel> reference_model_;
  std::vector<Offset> offsets_;
  std::function<void(const std::string&)> note_;
  survey::ClearanceLevel level_ = survey::ClearanceLevel::Clear;
  std::string status_line_;
  std::uint64_t stations_ = 0, warning_stations_ = 0, alarm_stations_ = 0;
};

}  // namespace plumb::survey_component
