// The ISCWSA separation rule against ISCWSA's standard set of wellpaths for evaluating clearance
// scenarios (tests/data/iscwsa_clearance): the reference well and its 11 offset wells surveyed
// through plumb (minimum curvature, the ISCWSA MWD revision 4 model the set uses, first stations
// surveyed), then every reference station's closest approach and separation factor against the
// workbook's. The workbook rounds what it lists (distances to 0.01 m, pedal curve radii to 0.0001
// m, the sidetrack's to 0.01 m) and calculates its SF from the rounded values: a published SF
// carries that rounding, which the comparison allows for on top of its 0.1 %.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/csv/files.hpp"
#include "plumb/survey/clearance.hpp"
#include "plumb/survey/clearance_well_file.hpp"
#include "plumb/survey/closest_approach.hpp"
#include "plumb/survey/survey.hpp"
#include "plumb/survey/survey_inputs.hpp"

namespace plumb::survey {
namespace {

const std::string kSet = PLUMB_ISCWSA_CLEARANCE_DATA;
using Table = std::vector<std::map<std::string, double>>;

// A CSV of the set: its rows as columns by name.
Table read_table(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  Table out;
  std::vector<std::string> header;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto cells = csv::split_line(line);
    if (header.empty()) {
      header = cells;
      continue;
    }
    std::map<std::string, double> row;
    for (std::size_t i = 0; i < cells.size() && i < header.size(); ++i) row[header[i]] = std::stod(cells[i]);
    out.push_back(row);
  }
  return out;
}

Table wellpath(const std::string& name) { return read_table(kSet + "/" + name + ".wellpath.csv"); }

// The set's setup: grid north, no declination, dip 70 deg, 50000 nT, 9.80665 m/s^2, the ISCWSA MWD
// revision 4 model from the well's first station (MD 0, or a sidetrack's kick-off), each well
// from its own slot.
Survey survey_of(const Table& rows, double from_md_m = -1) {
  SurveyOptions o;
  o.reference = AzimuthReference::Grid;
  o.north.declination_known = o.north.convergence_known = true;
  o.field.gravity_mps2 = 9.80665;
  o.field.total_b_uT = 50;
  o.field.dip_deg = 70;
  o.checks = {false, false, false};
  o.tool_code = iscwsa::builtin_tool_code("MWD:rev4");
  o.first_station_surveyed = true;
  Table used;
  for (const auto& r : rows)
    if (r.at("md_m") >= from_md_m - 1e-9) used.push_back(r);
  o.tie_in = {used.front().at("north_m"), used.front().at("east_m"), used.front().at("tvd_m")};
  Survey survey(o);
  for (const auto& r : used) {
    Station s;
    s.md_m = r.at("md_m");
    s.inclination_deg = r.at("inclination_deg");
    s.magnetic_azimuth_deg = r.at("azimuth_deg");
    survey.add(s);
  }
  return survey;
}

// The workbook's hole: (36 in + 24 in) / 2 converted with 12 x 3.281 in per metre.
constexpr double kInchM = 1.0 / (12 * 3.281);
const SeparationRule kRule{3.5, 0.5, 0.3};

std::string offset_name(int number) {
  char name[16];
  std::snprintf(name, sizeof name, "offset-%02d", number);
  return name;
}

struct Compared {
  double sf_relative = 0;        // the largest |SF - published| / |published|
  double sf_beyond_rounding = 0;  // the same less what the workbook's rounding explains
  double distance_m = 0, offset_md_m = 0, reference_sigma_m = 0;
  int rows = 0;
};

// Rows where the workbook's offset pedal curve radius differs from the model's at that point by
// more than its rounding (listed in docs/surveys.md): 04 and 05 at single points between offset
// stations whose neighbours agree to 0.0001 m; 08 on its azimuth-90 path, whose listing differs
// from the model by up to 0.02 m.
const std::set<std::pair<int, double>> kOutliers{{4, 2640}, {5, 1290}, {8, 1980}};

Compared compare_offset(int number) {
  const std::string name = offset_name(number);
  // The sidetrack's uncertainty counts from its kick-off for both wells (the set's rule): the
  // reference surveyed again from there, tied in at its own position.
  const bool sidetrack = number == 10;
  const Table offset_rows = wellpath(name);
  const double kick_off = sidetrack ? offset_rows.front().at("md_m") : -1;
  const ClearanceWell reference = clearance_well(survey_of(wellpath("reference"), kick_off), "reference", 18 * kInchM);
  const ClearanceWell offset = clearance_well(survey_of(offset_rows), name, 12 * kInchM);
  const double digit = sidetrack ? 0.005 : 0.00005;  // half the last digit of the listed radii
  Compared w;
  for (const auto& e : read_table(kSet + "/" + name + ".clearance.csv")) {
    const double md = e.at("reference_md_m");
    const auto at = std::find_if(reference.stations.begin(), reference.stations.end(),
                                 [&](const WellPoint& p) { return std::abs(p.md_m - md) < 1e-6; });
    if (at == reference.stations.end()) {
      ADD_FAILURE() << name << ": no reference station at " << md;
      continue;
    }
    const StationClearance c = station_clearance(*at, reference.radius_m, offset, kRule);
    const double sf = e.at("separation_factor");
    const double error = std::abs(c.separation_factor - sf);
    // What the workbook's rounding of D (0.005 m) and of both radii moves its SF by.
    const double rounding = 0.005 / c.boundary_m + std::abs(c.separation_factor) * kRule.k * kRule.k *
                                                       (c.reference_sigma_m + c.offset_sigma_m) * digit /
                                                       (c.boundary_m * c.boundary_m);
    const std::string where = name + " at reference MD " + std::to_string(md);
    const double allowed = kOutliers.count({number, md}) ? 3e-3 : sidetrack ? 2.5e-2 : 1e-3;
    EXPECT_LE(error, allowed * std::abs(sf) + rounding) << where << ": SF " << c.separation_factor << " against " << sf;
    EXPECT_LE(std::abs(c.centre_to_centre_m - e.at("centre_to_centre_m")), 0.005 + 1e-6) << where;
    EXPECT_LE(std::abs(c.offset.md_m - e.at("offset_md_m")), 0.005 + 1e-6) << where;
    if (!sidetrack) {
      EXPECT_LE(std::abs(c.reference_sigma_m - e.at("reference_pcr_m")), 0.00015) << where;
    }
    ++w.rows;
    w.sf_relative = std::max(w.sf_relative, error / std::abs(sf));
    w.sf_beyond_rounding = std::max(w.sf_beyond_rounding, (error - rounding) / std::abs(sf));
    w.distance_m = std::max(w.distance_m, std::abs(c.centre_to_centre_m - e.at("centre_to_centre_m")));
    w.offset_md_m = std::max(w.offset_md_m, std::abs(c.offset.md_m - e.at("offset_md_m")));
    w.reference_sigma_m = std::max(w.reference_sigma_m, std::abs(c.reference_sigma_m - e.at("reference_pcr_m")));
  }
  std::printf("%s: %d rows, SF within %.3f %% (%.3f %% beyond the workbook's rounding), D within %.4f m, offset MD "
              "within %.4f m, reference sigma within %.4f m\n",
              name.c_str(), w.rows, 100 * w.sf_relative, 100 * std::max(0.0, w.sf_beyond_rounding), w.distance_m,
              w.offset_md_m, w.reference_sigma_m);
  return w;
}

// Every SF of the ten offsets in their own surveys (1000 reference stations) within 0.1 % beyond
// the workbook's rounding, three listed rows within 0.3 %; the sidetrack (69 stations) within
// 2.5 %; every distance and closest offset MD within the workbook's 0.005 m rounding.
TEST(IscwsaClearance, StandardSetMatchesTheWorkbook) {
  int rows = 0;
  for (int n = 1; n <= 11; ++n) rows += compare_offset(n).rows;
  EXPECT_EQ(rows, 10 * 100 + 69);
}

// The wells as surveyed through plumb against the set's listings: positions within their 0.005 m
// rounding, the 1-sigma high side, lateral and along-hole within 0.001 m (the listings' own
// rounding is 0.00005 m) for the reference and the offsets that hold azimuths other than 90 deg;
// without the first station's own errors (a tie-in) the vertical section alone is 0.0008 m low.
TEST(IscwsaClearance, WellsMatchTheListings) {
  std::vector<std::string> names{"reference"};
  for (int n : {1, 2, 3, 4, 5, 6, 7, 9}) names.push_back(offset_name(n));
  for (const auto& name : names) {
    const Table rows = wellpath(name);
    const Survey survey = survey_of(rows);
    ASSERT_EQ(survey.rows().size(), rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const SurveyRow& r = survey.rows()[k];
      const auto& e = rows[k];
      const std::string where = name + " MD " + std::to_string(e.at("md_m"));
      EXPECT_NEAR(r.point.north_m, e.at("north_m"), 0.005 + 1e-6) << where;
      EXPECT_NEAR(r.point.east_m, e.at("east_m"), 0.005 + 1e-6) << where;
      EXPECT_NEAR(r.point.tvd_m, e.at("tvd_m"), 0.005 + 1e-6) << where;
      const double inc = r.station.inclination_deg * kDeg, azi = r.azimuth_deg * kDeg;
      Eigen::Matrix3d hla;
      hla.row(0) << std::cos(inc) * std::cos(azi), std::cos(inc) * std::sin(azi), -std::sin(inc);
      hla.row(1) << -std::sin(azi), std::cos(azi), 0;
      hla.row(2) << std::sin(inc) * std::cos(azi), std::sin(inc) * std::sin(azi), std::cos(inc);
      const Eigen::Matrix3d c = hla * r.uncertainty.covariance * hla.transpose();
      EXPECT_NEAR(std::sqrt(c(0, 0)), e.at("sigma_h_m"), 1e-3) << where;
      EXPECT_NEAR(std::sqrt(c(1, 1)), e.at("sigma_l_m"), 1e-3) << where;
      EXPECT_NEAR(std::sqrt(c(2, 2)), e.at("sigma_a_m"), 1e-3) << where;
    }
  }
}

// A sidetrack's view of its parent, from the parent's station list: surveyed again from the
// kick-off. At a station, the stations below keep their places (the path is the parent's) and the
// uncertainty restarts (smaller at every station below than the whole well's); between stations,
// the first point is the parent's course at that depth. A survey file cannot be surveyed again.
TEST(IscwsaClearance, TheParentSeenFromASidetrackCountsFromTheKickOff) {
  const std::string parent = kSet + "/reference.wellpath.csv";
  StationListModel model;
  model.error_model = "MWD:rev4";
  model.dip_deg = 70;
  const ClearanceWell whole = read_clearance_well(parent, "reference", 0.4, model).well;
  for (const double kick_off : {900.0, 915.0}) {
    const ClearanceWell below = read_clearance_well_below(parent, "reference", 0.4, model, kick_off).well;
    ASSERT_DOUBLE_EQ(below.stations.front().md_m, kick_off);
    const auto after = std::find_if(whole.stations.begin(), whole.stations.end(),
                                    [&](const WellPoint& p) { return p.md_m >= kick_off; });
    const std::size_t k = static_cast<std::size_t>(after - whole.stations.begin());
    const WellPoint on_course = after->md_m == kick_off ? *after : interpolate_course(whole.stations[k - 1], *after, kick_off);
    EXPECT_LT((below.stations.front().position - on_course.position).norm(), 1e-9) << kick_off;
    ASSERT_EQ(below.stations.size(), whole.stations.size() - k + (after->md_m == kick_off ? 0 : 1)) << kick_off;
    for (std::size_t j = 1; j < below.stations.size(); ++j) {
      const WellPoint& b = below.stations[j];
      const WellPoint& w = whole.stations[k + j - (after->md_m == kick_off ? 0 : 1)];
      ASSERT_DOUBLE_EQ(b.md_m, w.md_m);
      EXPECT_LT((b.position - w.position).norm(), 1e-6) << kick_off << " at " << b.md_m;
      EXPECT_LT(b.covariance.trace(), w.covariance.trace()) << kick_off << " at " << b.md_m;
    }
  }
  EXPECT_THROW(read_clearance_well_below(parent, "reference", 0.4, model, whole.stations.back().md_m + 10),
               std::runtime_error);
}

// plumb-survey scans a sidetrack live: the well drilled goes into a SidetrackView one station at a
// time, and each station's point as the sidetrack sees it is scanned at once. It is the whole
// well's view at the same station (later stations change nothing above them), so the live rows are
// the offline ones: a kick-off between stations, and one at a station (the live well reaching it).
TEST(IscwsaClearance, TheSidetrackViewStationByStationIsTheWholeWells) {
  const std::string parent = kSet + "/reference.wellpath.csv";
  StationListModel model;
  model.error_model = "MWD:rev4";
  model.dip_deg = 70;
  const std::vector<Station> stations = read_station_csv(parent);
  const ClearanceWell whole = read_clearance_well(parent, "reference", 0.4, model).well;
  ASSERT_EQ(stations.size(), whole.stations.size());
  for (const double kick_off : {915.0, 900.0}) {
    const ClearanceWell below = read_clearance_well_below(parent, "reference", 0.4, model, kick_off).well;
    SidetrackView view(kick_off, model, "live");
    std::size_t seen = 0;
    for (std::size_t i = 0; i < stations.size(); ++i) {
      const auto live = view.add(stations[i], whole.stations[i]);
      ASSERT_EQ(live.has_value(), stations[i].md_m >= kick_off) << kick_off << " at " << stations[i].md_m;
      if (!live) continue;
      ASSERT_DOUBLE_EQ(live->md_m, stations[i].md_m);
      const auto same = std::find_if(below.stations.begin(), below.stations.end(),
                                     [&](const WellPoint& p) { return p.md_m == live->md_m; });
      ASSERT_NE(same, below.stations.end()) << kick_off << " at " << live->md_m;
      EXPECT_LT((live->position - same->position).norm(), 1e-9) << kick_off << " at " << live->md_m;
      EXPECT_LE((live->covariance - same->covariance).norm(), 1e-9 * (1 + same->covariance.norm()))
          << kick_off << " at " << live->md_m;
      ++seen;
    }
    // Every station from the kick-off down: the list below it, less its first point when that one
    // was interpolated between two stations.
    const bool at_a_station =
        std::any_of(stations.begin(), stations.end(), [&](const Station& st) { return st.md_m == kick_off; });
    EXPECT_EQ(seen, below.stations.size() - (at_a_station ? 0 : 1)) << kick_off;
    ASSERT_NE(view.survey(), nullptr);
  }
  // A kick-off above the well's first station: said, naming what was given.
  SidetrackView early(whole.stations[2].md_m - 1, model, "the well drilled");
  try {
    early.add(stations[3], whole.stations[3]);
    ADD_FAILURE() << "a kick-off above the first station was taken";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("the well drilled: the sidetrack's kick-off at MD"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plumb::survey
