// The wells of a clearance scan, from files: a plumb survey file (its rows' positions and position
// covariances, as the survey that wrote it made them), or a station list CSV (md_m,
// inclination_deg, azimuth_deg in the wells' common north), surveyed here through an error model
// from the position its first row gives (north_m, east_m, tvd_m: the well's slot or tie-in).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "plumb/survey/clearance.hpp"
#include "plumb/survey/iscwsa.hpp"

namespace plumb::survey {

// How a station list is surveyed: its error model (a built-in tool code or a tool code file) and
// the reference field the model weighs.
struct StationListModel {
  std::string error_model = "MWD";
  // A tool code built rather than named (the navigator's own gyro model): used instead of error_model.
  std::optional<iscwsa::ToolCode> tool_code;
  // A survey program's later legs (SurveyOptions::later_legs): the survey's own, for a sidetrack.
  std::vector<iscwsa::Leg> later_legs;
  double gravity_mps2 = kStandardGravity, total_b_uT = 50, dip_deg = 60;
  double latitude_deg = std::numeric_limits<double>::quiet_NaN();
  bool first_station_surveyed = true;  // a well surveyed from its first station (docs/surveys.md)
};

struct ClearanceWellFile {
  ClearanceWell well;
  std::string azimuth_reference;  // "true" or "grid" (a survey file's), or "as listed" (a station list)
  std::string error_model;        // the tool code the covariances come from
};

// Reads `path`: a survey file when its first line is the survey format line, else a station list.
// A survey file's covariance between its stations is interpolated linearly in measured depth (its
// options are not in the file); a station list's is its error model's at the point. Throws
// std::runtime_error naming the file (and line) for anything it cannot use: a magnetic survey (its
// north moves with the field), a station list without its first row's position, a bad number.
ClearanceWellFile read_clearance_well(const std::string& path, const std::string& name, double radius_m,
                                      const StationListModel& model);

// The same well seen from a sidetrack that kicks off it at `kick_off_md_m`: the part below, surveyed
// again from there (the point on the course at that depth, tied in at its own position: the two
// wells' uncertainty counts from their common point, ISCWSA's rule for a sidetrack). Only a station
// list can be surveyed again (a survey file's error terms are not in it): std::runtime_error for a
// survey file, and for a kick-off outside the well.
ClearanceWellFile read_clearance_well_below(const std::string& path, const std::string& name, double radius_m,
                                            const StationListModel& model, double kick_off_md_m);

// The same from the well's stations as a station list holds them (md, inclination, azimuth in the
// wells' common north) and its course at those stations (`course[i]` the point of `stations[i]`),
// through a SidetrackView. std::runtime_error naming `where` for a kick-off outside the course.
ClearanceWellFile clearance_well_below(const std::vector<Station>& stations, const std::vector<WellPoint>& course,
                                       const std::string& where, const std::string& name, double radius_m,
                                       const StationListModel& model, double kick_off_md_m);

// A well seen from a sidetrack that kicks off it at `kick_off_md_m`, built station by station: the
// well's stations in order, each with its point on the well's course. The first point is the
// course at the kick-off (at a station, or interpolated between the two around it, with its
// direction there), tied in at its own position and surveyed as the first station; every station
// below follows, through the station-list model. What `plumb clearance --sidetrack` does with a
// file (clearance_well_below) and plumb-survey with the well it is drilling, one station at a time:
// a station's point does not change with the stations after it, so both see the same points.
class SidetrackView {
 public:
  // Throws for an error model that cannot be read (as clearance_tool_code).
  SidetrackView(double kick_off_md_m, StationListModel model, std::string where);

  // The well's next station and its point on the course. Its point as the sidetrack sees it, or
  // nothing above the kick-off. Throws std::runtime_error naming `where` for a station the survey
  // refuses, and for a kick-off above the well's first station.
  std::optional<WellPoint> add(const Station& station, const WellPoint& course_point);
  double kick_off_md_m() const { return kick_off_md_m_; }
  // The well's stations from the next on are priced by `tool` (Survey::start_leg); all of them when
  // the kick-off has not been reached.
  void start_leg(const iscwsa::ToolCode& tool);
  // The survey from the kick-off; null until a station reached it.
  const Survey* survey() const { return survey_ ? &*survey_ : nullptr; }

 private:
  double kick_off_md_m_;
  StationListModel model_;
  std::string where_;
  std::optional<std::pair<Station, WellPoint>> above_;  // the last station above the kick-off
  std::optional<Survey> survey_;
};

}  // namespace plumb::survey
