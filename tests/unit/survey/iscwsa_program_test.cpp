// A well surveyed in legs (iscwsa::Leg): on a straight tangent, where a constant azimuth error
// moves each station sideways by the length of hole it weighs, the position errors are known in
// closed form; a gyro leg's run starts at its own first station.
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/survey/iscwsa.hpp"
#include "plumb/survey/survey.hpp"

namespace plumb::survey::iscwsa {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kInc = 60, kAzi = 30;

// A tangent at 60 deg inclination toward 30 deg, stations every 30 m from the tie-in at 0 to 1200 m.
std::vector<Station> tangent(double from_md = 0) {
  std::vector<Station> s;
  for (double md = from_md; md <= 1200 + 1e-9; md += 30)
    s.push_back({md, kInc, kAzi, kAzi, (md - from_md) * std::cos(kInc * kDeg), std::numeric_limits<double>::quiet_NaN()});
  return s;
}

ToolCode azimuth_only(const char* name, Propagation p, double sd_deg = 0.5) {
  ToolCode t;
  t.name = name;
  t.terms.push_back({"AZ", "AZ", sd_deg, "deg", p});
  return t;
}

// The variance across the tangent's azimuth, horizontally, at the last station.
double across(const Result& r) {
  const Eigen::Vector3d side(-std::sin(kAzi * kDeg), std::cos(kAzi * kDeg), 0);
  return side.dot(r.total.back() * side);
}

TEST(IscwsaProgram, ASystematicTermIsEachLegsOwnDrawAPerWellTermOneDraw) {
  const std::vector<Station> s = tangent();
  const double per_m = std::sin(kInc * kDeg) * 0.5 * kDeg;  // sideways, per metre of hole weighed
  // The tie-in weighs nothing; each station the half courses around it; the last its upper half:
  // 1185 m in all. Split at 600 m: the first leg's stations weigh 570 m (its last, 570 m, weighs
  // the course to 600 m), the second's 615 m.
  const Result one = propagate(s, azimuth_only("A", Propagation::Systematic), Field{});
  EXPECT_NEAR(across(one), std::pow(1185 * per_m, 2), 1e-9);
  const std::vector<Leg> legs = {{-std::numeric_limits<double>::infinity(), azimuth_only("A", Propagation::Systematic)},
                                 {600, azimuth_only("B", Propagation::Systematic)}};
  const Result two = propagate(s, legs, Field{});
  EXPECT_NEAR(across(two), std::pow(570 * per_m, 2) + std::pow(615 * per_m, 2), 1e-9);
  ASSERT_EQ(two.codes.size(), 2u);
  EXPECT_EQ(two.codes[0], "A: AZ");
  EXPECT_EQ(two.codes[1], "B: AZ");
  // Below the first leg its error moves the stations rigidly: at 900 m as at its last station's
  // half course below (570 m).
  const Eigen::Vector3d side(-std::sin(kAzi * kDeg), std::cos(kAzi * kDeg), 0);
  EXPECT_NEAR(side.dot(two.per_term[0][30] * side), std::pow(570 * per_m, 2), 1e-9);
  // Per well: the two legs' errors are one draw.
  const std::vector<Leg> well = {{-std::numeric_limits<double>::infinity(), azimuth_only("A", Propagation::WellByWell)},
                                 {600, azimuth_only("B", Propagation::WellByWell)}};
  const Result shared = propagate(s, well, Field{});
  EXPECT_NEAR(across(shared), std::pow(1185 * per_m, 2), 1e-9);
  ASSERT_EQ(shared.codes.size(), 1u);
  EXPECT_EQ(shared.codes[0], "AZ");
  // Each station's own angles are its leg's.
  const Result tight = propagate(s, {{-std::numeric_limits<double>::infinity(), azimuth_only("A", Propagation::Systematic)},
                                     {600, azimuth_only("B", Propagation::Systematic, 0.1)}},
                                 Field{});
  EXPECT_NEAR(std::sqrt(tight.angle_variance[19](1)) / kDeg, 0.5, 1e-12);
  EXPECT_NEAR(std::sqrt(tight.angle_variance[20](1)) / kDeg, 0.1, 1e-12);
}

TEST(IscwsaProgram, AContinuousGyroLegDriftsFromItsOwnFirstStation) {
  ToolCode gyro;
  gyro.name = "gyro";
  gyro.gyro.continuous = true;
  gyro.gyro.initialisation = GyroInitialisation::Reference;
  gyro.gyro.running_speed_m_per_h = 600;
  gyro.terms.push_back({"GD", "GXYZ-GD", 1.0, "deg/hr", Propagation::Systematic});
  const std::vector<Leg> legs = {{-std::numeric_limits<double>::infinity(), azimuth_only("A", Propagation::Systematic)},
                                 {600, gyro}};
  const Result program = propagate(tangent(), legs, Field{});
  // The gyro leg alone, as a well tied in at 600 m: its first station drifted nothing, so it
  // weighs as a tie-in does.
  const Result alone = propagate(tangent(600), gyro, Field{});
  ASSERT_EQ(program.codes.size(), 2u);
  EXPECT_EQ(program.codes[1], "gyro: GD");
  const Eigen::Matrix3d& p = program.per_term[1].back();
  const Eigen::Matrix3d& a = alone.per_term[0].back();
  EXPECT_LT((p - a).norm(), 1e-9 * a.norm());
  EXPECT_GT(a.norm(), 1.0);  // 1 deg/h over an hour of the leg: metres
  // Above the leg, nothing of it.
  EXPECT_EQ(program.per_term[1][19].norm(), 0.0);
}

TEST(IscwsaProgram, ALegBelowTheLastStationChangesNothingYet) {
  ToolCode gyro = builtin_tool_code("GYRO:mems");
  const ToolCode mwd = builtin_tool_code("MWD");
  const std::vector<Station> s = tangent();
  for (const ToolCode& next : {gyro, mwd}) {
    const Result program = propagate(s, {{-std::numeric_limits<double>::infinity(), mwd}, {1300, next}}, Field{});
    const Result one = propagate(s, mwd, Field{});
    EXPECT_LT((program.total.back() - one.total.back()).norm(), 1e-12 * one.total.back().norm()) << next.name;
  }
}

TEST(IscwsaProgram, LegsOutOfOrderAreRefused) {
  const std::vector<Leg> legs = {{-std::numeric_limits<double>::infinity(), azimuth_only("A", Propagation::Systematic)},
                                 {600, azimuth_only("B", Propagation::Systematic)},
                                 {600, azimuth_only("C", Propagation::Systematic)}};
  EXPECT_THROW(propagate(tangent(), legs, Field{}), std::invalid_argument);
  EXPECT_THROW(propagate(tangent(), std::vector<Leg>{}, Field{}), std::invalid_argument);
}

}  // namespace
}  // namespace plumb::survey::iscwsa

namespace plumb::survey {
namespace {

// A survey priced by one tool, re-tuned while drilling: the stations already surveyed keep their
// uncertainty; those below are priced by the program of both legs.
TEST(SurveyProgram, ALegStartedWhileSurveyingPricesTheStationsBelowIt) {
  SurveyOptions o;
  o.tool_code = iscwsa::builtin_tool_code("MWD:rev4");
  Survey survey(o);
  const auto station = [](double md) {
    Station s;
    s.t_s = md;  // a second a metre
    s.md_m = md;
    s.inclination_deg = 60;
    s.magnetic_azimuth_deg = 30;
    return s;
  };
  for (double md = 0; md <= 600; md += 30) survey.add(station(md));
  const Eigen::Matrix3d at_600 = survey.rows().back().uncertainty.covariance;
  iscwsa::ToolCode gyro = iscwsa::builtin_tool_code("GYRO:mems");
  survey.start_leg(gyro);
  EXPECT_EQ(survey.rows().back().uncertainty.covariance, at_600);
  for (double md = 630; md <= 1200; md += 30) survey.add(station(md));
  EXPECT_EQ(survey.rows()[20].uncertainty.covariance, at_600);
  EXPECT_EQ(survey.rows()[20].error_model, o.tool_code->name);
  EXPECT_EQ(survey.rows()[21].error_model, gyro.name);
  // The same stations through the program at once.
  std::vector<iscwsa::Station> stations;
  for (const SurveyRow& r : survey.rows())
    stations.push_back({r.station.md_m, r.station.inclination_deg, r.azimuth_deg, r.station.magnetic_azimuth_deg,
                        r.point.tvd_m, r.station.t_s});
  iscwsa::ToolCode mwd = *o.tool_code;
  std::erase_if(mwd.terms, [](const iscwsa::Term& t) { return t.weight_function == "AZ" || t.weight_function == "DBH"; });
  const iscwsa::Result program = iscwsa::propagate(
      stations, std::vector<iscwsa::Leg>{{-std::numeric_limits<double>::infinity(), mwd}, {600.5, gyro}}, iscwsa::Field{});
  const Eigen::Matrix3d& end = survey.rows().back().uncertainty.covariance;
  EXPECT_LT((end - program.total.back()).norm(), 1e-9 * end.norm());
  // Neither tool alone: the gyro's leg is not the MWD tool's.
  const iscwsa::Result mwd_only = iscwsa::propagate(stations, mwd, iscwsa::Field{});
  EXPECT_GT((end - mwd_only.total.back()).norm(), 0.01 * end.norm());
}

TEST(SurveyProgram, ALegStartedWhileSurveyingKeepsTheLegsGivenBelow) {
  SurveyOptions o;
  o.tool_code = iscwsa::builtin_tool_code("GYRO:tactical");
  o.later_legs.push_back({900, iscwsa::builtin_tool_code("MWD")});
  Survey survey(o);
  Station s;
  s.inclination_deg = 60;
  s.magnetic_azimuth_deg = 30;
  const auto add_to = [&](double to) {
    for (; s.md_m <= to; s.md_m += 30, s.t_s += 30) survey.add(s);
  };
  add_to(600);
  survey.start_leg(iscwsa::builtin_tool_code("GYRO:mems"));
  survey.start_leg(iscwsa::builtin_tool_code("GYRO:mems"));  // again before another station: one leg
  add_to(1200);
  ASSERT_EQ(survey.options().later_legs.size(), 2u);
  std::vector<std::string> names;
  for (const SurveyRow& r : survey.rows()) names.push_back(r.error_model.substr(0, r.error_model.find(' ')));
  std::vector<std::string> want(21, "GYRO:tactical");
  want.resize(30, "GYRO:mems");
  want.resize(41, "MWD");
  EXPECT_EQ(names, want);
}

TEST(SurveyProgram, LegsNeedAToolCodeAboveThem) {
  SurveyOptions o;  // plumb's own propagation
  Survey survey(o);
  EXPECT_THROW(survey.start_leg(iscwsa::builtin_tool_code("MWD")), std::invalid_argument);
  o.later_legs.push_back({600, iscwsa::builtin_tool_code("MWD")});
  EXPECT_THROW(Survey{o}, std::invalid_argument);
}

}  // namespace
}  // namespace plumb::survey
