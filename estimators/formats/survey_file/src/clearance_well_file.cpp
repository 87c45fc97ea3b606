#include "plumb/survey/clearance_well_file.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>
#include <vector>

#include "plumb/core/number.hpp"
#include "plumb/survey/closest_approach.hpp"
#include "plumb/csv/files.hpp"
#include "plumb/survey/survey_file.hpp"
#include "plumb/survey/survey_inputs.hpp"
#include "plumb/survey/tool_code_file.hpp"

namespace plumb::survey {
namespace {

// The rows of a CSV with named columns, as text.
struct ClearanceCsv {
  std::map<std::string, std::size_t> columns;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::size_t> lines;
};

ClearanceCsv clearance_read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open '" + path + "'");
  ClearanceCsv t;
  std::size_t line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    auto cells = csv::split_line(line);
    if (t.columns.empty()) {
      for (std::size_t i = 0; i < cells.size(); ++i) t.columns[cells[i]] = i;
      continue;
    }
    t.rows.push_back(std::move(cells));
    t.lines.push_back(line_no);
  }
  if (t.columns.empty()) throw std::runtime_error(path + ": no header line");
  if (t.rows.empty()) throw std::runtime_error(path + ": no stations");
  return t;
}

double clearance_number(const ClearanceCsv& t, std::size_t row, const std::string& column, const std::string& path) {
  const auto it = t.columns.find(column);
  if (it == t.columns.end()) throw std::runtime_error(path + ": no column '" + column + "' in the header");
  const auto& cells = t.rows[row];
  const std::string text = it->second < cells.size() ? cells[it->second] : std::string();
  const auto v = parse_number(text, true);
  if (!v || !std::isfinite(*v))
    throw std::runtime_error(path + ":" + std::to_string(t.lines[row]) + ": column '" + column + "': bad number '" +
                             text + "'");
  return *v;
}

bool clearance_is_survey_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open '" + path + "'");
  std::string first;
  std::getline(in, first);
  return first.rfind("# plumb survey", 0) == 0;
}

ClearanceWellFile clearance_from_survey_file(const std::string& path, const std::string& name, double radius_m) {
  const ClearanceCsv t = clearance_read_csv(path);
  ClearanceWellFile f;
  f.well.name = name;
  f.well.radius_m = radius_m;
  const auto text = [&](std::size_t r, const std::string& c) {
    const auto it = t.columns.find(c);
    return it == t.columns.end() || it->second >= t.rows[r].size() ? std::string() : t.rows[r][it->second];
  };
  f.azimuth_reference = text(0, "azimuth_reference");
  f.error_model = text(0, "error_model");
  if (f.azimuth_reference == "magnetic")
    throw std::runtime_error(path + ": a magnetic survey (its north moves with the field): survey it with --reference "
                                    "true or grid for a clearance scan");
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto n = [&](const std::string& c) { return clearance_number(t, r, c, path); };
    WellPoint p;
    p.md_m = n("md_m");
    p.inclination_deg = n("inclination_deg");
    p.azimuth_deg = n("azimuth_deg");
    p.position = {n("north_m"), n("east_m"), n("tvd_m")};
    p.covariance << n("cov_nn"), n("cov_ne"), n("cov_nd"), n("cov_ne"), n("cov_ee"), n("cov_ed"), n("cov_nd"),
        n("cov_ed"), n("cov_dd");
    if (!f.well.stations.empty() && !(p.md_m > f.well.stations.back().md_m))
      throw std::runtime_error(path + ":" + std::to_string(t.lines[r]) + ": measured depth does not increase");
    f.well.stations.push_back(p);
  }
  return f;
}

iscwsa::ToolCode clearance_tool_code(const std::string& name) {
  const auto builtin = iscwsa::builtin_tool_codes();
  for (const auto& b : builtin)
    if (b == name) return iscwsa::builtin_tool_code(name);
  std::ifstream in(name);
  if (!in) return iscwsa::builtin_tool_code(name);  // names the built-in codes in its error
  return iscwsa::read_tool_code(in, name);
}

std::string clearance_md_text(double md_m) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", md_m);
  return text;
}

// How a station list is surveyed from `tie_in` (north, east, TVD) through the model.
SurveyOptions station_list_options(const StationListModel& model, const Eigen::Vector3d& tie_in) {
  SurveyOptions o;
  o.reference = AzimuthReference::Grid;  // the azimuths as listed: no correction
  o.north.declination_known = o.north.convergence_known = true;
  o.field.gravity_mps2 = model.gravity_mps2;
  o.field.total_b_uT = model.total_b_uT;
  o.field.dip_deg = model.dip_deg;
  o.checks = {false, false, false};
  o.tool_code = model.tool_code ? *model.tool_code : clearance_tool_code(model.error_model);
  o.later_legs = model.later_legs;
  o.latitude_deg = model.latitude_deg;
  o.first_station_surveyed = model.first_station_surveyed;
  o.tie_in = tie_in;
  return o;
}

// A station list surveyed from `tie_in` through the model.
ClearanceWellFile clearance_surveyed(const std::vector<Station>& stations, const Eigen::Vector3d& tie_in,
                                     const std::string& path, const std::string& name, double radius_m,
                                     const StationListModel& model) {
  Survey survey(station_list_options(model, tie_in));
  try {
    for (const Station& s : stations) survey.add(s);
  } catch (const StationError& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return {clearance_well(survey, name, radius_m), "as listed", survey.options().tool_code->name};
}

// The station list's stations and the position its first row gives.
std::pair<std::vector<Station>, Eigen::Vector3d> clearance_station_list(const std::string& path) {
  const ClearanceCsv t = clearance_read_csv(path);
  for (const char* c : {"north_m", "east_m", "tvd_m"})
    if (!t.columns.count(c))
      throw std::runtime_error(path + ": no column '" + std::string(c) +
                               "': a station list's first row places the well (north_m, east_m, tvd_m)");
  const Eigen::Vector3d tie_in{clearance_number(t, 0, "north_m", path), clearance_number(t, 0, "east_m", path),
                               clearance_number(t, 0, "tvd_m", path)};
  try {
    return {read_station_csv(path), tie_in};
  } catch (const StationError& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

ClearanceWellFile clearance_from_station_list(const std::string& path, const std::string& name, double radius_m,
                                              const StationListModel& model) {
  const auto [stations, tie_in] = clearance_station_list(path);
  return clearance_surveyed(stations, tie_in, path, name, radius_m, model);
}

}  // namespace

ClearanceWellFile read_clearance_well(const std::string& path, const std::string& name, double radius_m,
                                      const StationListModel& model) {
  if (clearance_is_survey_file(path)) return clearance_from_survey_file(path, name, radius_m);
  return clearance_from_station_list(path, name, radius_m, model);
}

ClearanceWellFile read_clearance_well_below(const std::string& path, const std::string& name, double radius_m,
                                            const StationListModel& model, double kick_off_md_m) {
  if (clearance_is_survey_file(path))
    throw std::runtime_error(path + ": a survey file cannot be surveyed again from a sidetrack's kick-off (its error "
                                    "terms are not in it): give the well as a station list");
  const auto [stations, tie_in] = clearance_station_list(path);
  // The whole well first: where the kick-off's point is, and its direction there.
  const ClearanceWell whole = clearance_surveyed(stations, tie_in, path, name, radius_m, model).well;
  return clearance_well_below(stations, whole.stations, path, name, radius_m, model, kick_off_md_m);
}

ClearanceWellFile clearance_well_below(const std::vector<Station>& stations, const std::vector<WellPoint>& p,
                                       const std::string& where, const std::string& name, double radius_m,
                                       const StationListModel& model, double kick_off_md_m) {
  if (p.size() != stations.size() || p.empty())
    throw std::invalid_argument(where + ": a well's course must have one point per station");
  if (!(kick_off_md_m >= p.front().md_m && kick_off_md_m <= p.back().md_m))
    throw std::runtime_error(where + ": the sidetrack's kick-off at MD " + clearance_md_text(kick_off_md_m) +
                             " m is not within the well (MD " + clearance_md_text(p.front().md_m) + " to " +
                             clearance_md_text(p.back().md_m) + " m)");
  SidetrackView view(kick_off_md_m, model, where);
  for (std::size_t i = 0; i < stations.size(); ++i) view.add(stations[i], p[i]);
  return {clearance_well(*view.survey(), name, radius_m), "as listed", view.survey()->options().tool_code->name};
}

SidetrackView::SidetrackView(double kick_off_md_m, StationListModel model, std::string where)
    : kick_off_md_m_(kick_off_md_m), model_(std::move(model)), where_(std::move(where)) {
  model_.first_station_surveyed = true;  // the kick-off is the well's first station surveyed
  // A tool code that cannot be read is said now, not at the kick-off.
  if (!model_.tool_code) clearance_tool_code(model_.error_model);
}

void SidetrackView::start_leg(const iscwsa::ToolCode& tool) {
  if (survey_) {
    survey_->start_leg(tool);
    return;
  }
  // Not at the kick-off yet: from below the last station seen (or the whole well before any).
  if (above_)
    iscwsa::insert_leg(model_.later_legs, {above_->first.md_m + kDuplicateDepthM, tool});
  else
    model_.tool_code = tool, model_.error_model = tool.name;
}

std::optional<WellPoint> SidetrackView::add(const Station& station, const WellPoint& course_point) {
  try {
    if (survey_) {
      survey_->add(station);
      return well_point(survey_->rows().back());
    }
    if (course_point.md_m < kick_off_md_m_) {
      above_ = std::make_pair(station, course_point);
      return std::nullopt;
    }
    // The kick-off: at this station, or on the course between the one above and this one.
    const bool at_station = course_point.md_m == kick_off_md_m_;
    if (!at_station && !above_)
      throw std::runtime_error(where_ + ": the sidetrack's kick-off at MD " + clearance_md_text(kick_off_md_m_) +
                               " m is above the well's first station (MD " + clearance_md_text(course_point.md_m) + " m)");
    const WellPoint at = at_station ? course_point : interpolate_course(above_->second, course_point, kick_off_md_m_);
    Station first = at_station ? station : above_->first;
    first.md_m = kick_off_md_m_;
    first.inclination_deg = at.inclination_deg;
    first.magnetic_azimuth_deg = at.azimuth_deg;
    survey_.emplace(station_list_options(model_, at.position));
    survey_->add(first);
    if (!at_station) survey_->add(station);
    return well_point(survey_->rows().back());
  } catch (const StationError& e) {
    throw std::runtime_error(where_ + ": " + e.what());
  }
}

}  // namespace plumb::survey
