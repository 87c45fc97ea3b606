// The ISCWSA gyro model against the worked examples of its paper (SPE 90408, Torkildsen et al.):
// the Example Models of Appendix D (tests/data/spe90408/model_N.tool.csv) on ISCWSA test well #1
// (the well of the MWD workbooks, tests/data/iscwsa) at latitude 60 deg N, in the UTM grid of
// Appendix E, against the position covariances of its Table E1. The paper's own acceptance is 1 %,
// or 2 m^2 where the published value is below 200 (it rounds to whole m^2); what plumb reaches is
// held here, tighter.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/csv/files.hpp"
#include "plumb/survey/iscwsa.hpp"
#include "plumb/survey/minimum_curvature.hpp"
#include "plumb/survey/tool_code_file.hpp"
#include "data_rows.hpp"

namespace plumb::survey::iscwsa {
namespace {

const std::string kExamples = PLUMB_SPE90408_DATA;
const std::string kWell = PLUMB_ISCWSA_DATA "/mwdrev5-iscwsa-1.wellpath.csv";
// Appendix E gives well #1 in a UTM grid, its azimuths grid azimuths, while the gyro reads true
// north: true = grid - 0.866 deg, the convergence 1 deg west of a zone's central meridian at
// 60 deg N (as at 2 deg E in UTM zone 31); inferred from Table E1, not from a published location
// (README.md).
const double kWell1Convergence =
    std::atan(std::tan(-std::numbers::pi / 180) * std::sin(std::numbers::pi / 3)) * 180 / std::numbers::pi;

std::vector<Station> well1() {
  std::vector<StationGeometry> g;
  for (const auto& r : test::data_rows(kWell)) g.push_back({std::stod(r[0]), std::stod(r[1]), std::stod(r[2])});
  const auto path = minimum_curvature(g);
  std::vector<Station> s;
  for (std::size_t k = 0; k < g.size(); ++k)
    s.push_back({g[k].md_m, g[k].inclination_deg, g[k].azimuth_deg, g[k].azimuth_deg, path[k].tvd_m});
  return s;
}

// Beyond the table's rounding to whole m^2, values of 200 m^2 and more within 0.1 %; Model #2 within
// 0.25 % (not explained: at 2100 m NE -374.7 against -376), Model #4 within 0.12 % (5100 m NN 0.11 %
// high; its z gyro hands over to x-y gyros inside a course, shared at 17 deg; counting the course
// whole to the x-y gyros left it 0.22 % high, whole to the z gyro 0.13 % low at 8000 m). Values
// below 200 m^2 within 1.25 m^2 (1200 m EE 17.1 against 18, the vertical section's misalignments;
// Model #1 at 2100 m EE 142.8 against 144).
bool within_what_plumb_reaches(int model, double ours, double published) {
  const double gap = std::abs(ours - published);
  if (std::abs(published) < 200) return gap <= 1.25;
  const double relative = model == 2 ? 0.0025 : model == 4 ? 0.0012 : 0.001;
  return gap <= 0.5 + relative * std::abs(published);
}

TEST(Spe90408, ExampleModelsOnTestWell1MatchAppendixE) {
  const std::vector<Station> stations = well1();
  Field field;
  field.latitude_deg = 60;
  field.true_azimuth_offset_deg = kWell1Convergence;
  std::map<int, Result> results;
  int checked = 0;
  for (const auto& row : test::data_rows(kExamples + "/well1.expected.csv")) {
    const int model = std::stoi(row[0]);
    if (!results.count(model)) {
      const std::string name = kExamples + "/model_" + std::to_string(model) + ".tool.csv";
      std::ifstream in(name);
      results.emplace(model, propagate(stations, read_tool_code(in, name), field));
    }
    const double md = std::stod(row[1]);
    std::size_t k = 0;
    while (k < stations.size() && std::abs(stations[k].md_m - md) > 1e-6) ++k;
    ASSERT_LT(k, stations.size()) << "no station at MD " << md;
    const Eigen::Matrix3d& c = results.at(model).total[k];
    const double ours[6] = {c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2)};
    const char* names[6] = {"NN", "NE", "NV", "EE", "EV", "VV"};
    std::printf("model %d MD %6.0f", model, md);
    for (std::size_t i = 0; i < 6; ++i) {
      const double published = std::stod(row[2 + i]);
      std::printf("  %s %.1f (%g)", names[i], ours[i], published);
      EXPECT_TRUE(within_what_plumb_reaches(model, ours[i], published))
          << "model " << model << " MD " << md << " " << names[i] << ": " << ours[i] << " against " << published;
      ++checked;
    }
    std::printf("\n");
  }
  EXPECT_EQ(checked, 26 * 6);  // every row of Table E1
}

}  // namespace
}  // namespace plumb::survey::iscwsa
