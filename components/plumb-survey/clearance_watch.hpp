// plumb-survey's anti-collision: each new station of the well being drilled against every offset
// well (read once, at start) by the ISCWSA separation rule, and the level of the least clear one,
// said when it changes (docs/surveys.md, "Anti-collision").
#pragma once

#include <cstdint>
#include <functional>
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

  // Reads the offset wells (station lists through `model`). Throws std::invalid_argument for a
  // survey whose north is magnetic (it moves with the field: no common frame with the offsets) and
  // for options that cannot work; std::runtime_error naming the file for an offset it cannot read.
  ClearanceWatch(const components::ClearanceCliOptions& options, const survey::StationListModel& model,
                 survey::AzimuthReference survey_reference, std::function<void(const std::string&)> note);

  bool active() const { return !offsets_.empty(); }
  // The survey's newest station against every offset well.
  std::vector<Pair> at_station(const survey::SurveyRow& row);

  survey::ClearanceLevel level() const { return level_; }
  const survey::ClearanceLevels& levels() const { return options_.levels; }
  // The newest station's least clear pair, in a line; empty while clear or before any station.
  const std::string& status_line() const { return status_line_; }
  std::vector<std::pair<std::string, std::uint64_t>> counters() const;

 private:
  components::ClearanceCliOptions options_;
  std::vector<survey::ClearanceWellFile> offsets_;
  std::function<void(const std::string&)> note_;
  survey::ClearanceLevel level_ = survey::ClearanceLevel::Clear;
  std::string status_line_;
  std::uint64_t stations_ = 0, warning_stations_ = 0, alarm_stations_ = 0;
};

}  // namespace plumb::survey_component
