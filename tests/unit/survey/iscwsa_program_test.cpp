// A well surveyed in legs (iscwsa::Leg): on a straight tangent, where a constant azimuth error
// moves each station sideways by the length of hole it weighs, the position errors are known in
// closed form; a gyro leg's run starts at its own first station.
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/survey/iscwsa.hpp"

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

TEST(IscwsaProgram, LegsOutOfOrderAreRefused) {
  const std::vector<Leg> legs = {{-std::numeric_limits<double>::infinity(), azimuth_only("A", Propagation::Systematic)},
                                 {600, azimuth_only("B", Propagation::Systematic)},
                                 {600, azimuth_only("C", Propagation::Systematic)}};
  EXPECT_THROW(propagate(tangent(), legs, Field{}), std::invalid_argument);
  EXPECT_THROW(propagate(tangent(), std::vector<Leg>{}, Field{}), std::invalid_argument);
}

}  // namespace
}  // namespace plumb::survey::iscwsa
