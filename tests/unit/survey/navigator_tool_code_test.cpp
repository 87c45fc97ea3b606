// The gyro model of the navigator's own stations (plumb/survey/navigator_tool_code.hpp): its
// figures are the navigator's (the presets the navigator itself reads, and figures given over
// them), its initialisation the navigator's alignment, and the model's azimuth sigma grows as the
// figures say it must.
#include "plumb/survey/navigator_tool_code.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "plumb/core/imu_grade.hpp"
#include "plumb/strapdown/parameters.hpp"

namespace plumb::survey::iscwsa {
namespace {

constexpr double kNavDeg = std::numbers::pi / 180.0;
constexpr double kNavDegPerHour = kNavDeg / 3600.0;  // deg/h in rad/s

// What `plumb param dump HOST strapdown` gives: every declared parameter, the given ones changed.
NavigatorParameters navigator_dump(const std::vector<std::pair<std::string, std::string>>& given = {}) {
  NavigatorParameters p;
  for (const auto& spec : strapdown::parameter_specs()) p[spec.name] = spec.default_value;
  for (const auto& [key, value] : given) p.at(key) = value;  // at: a name the navigator lacks fails here
  return p;
}

double term_magnitude(const ToolCode& tool, const std::string& code) {
  for (const Term& t : tool.terms)
    if (t.code == code) return t.magnitude;
  return std::numeric_limits<double>::quiet_NaN();
}

TEST(NavigatorToolCode, FiguresAreTheOnesTheNavigatorItselfReads) {
  for (const ImuGradeFigures& g : kImuGrades) {
    const NavigatorParameters p = navigator_dump({{"imu_grade", g.name}});
    const NavigatorModel m = navigator_tool_code(p);
    // The navigator's own reading of the same parameters: the same figures in its units.
    const strapdown::NavigatorConfig c = strapdown::parse_parameters(p);
    EXPECT_NEAR(term_magnitude(m.tool, "GXYZ-GD") * kNavDegPerHour, c.gyro_bias_sd, 1e-15) << g.name;
    EXPECT_NEAR(term_magnitude(m.tool, "GXYZ-GRW") * kNavDeg / 60.0, c.gyro_arw, 1e-15) << g.name;
    EXPECT_NEAR(term_magnitude(m.tool, "AXYZ-ZB"), c.accel_bias_sd, 1e-12) << g.name;
    EXPECT_NEAR(term_magnitude(m.tool, "AXYZ-SF"), c.accel_scale_sd, 1e-15) << g.name;
    EXPECT_NEAR(term_magnitude(m.tool, "AXYZ-MIS") * kNavDeg, c.accel_misalignment_sd, 1e-15) << g.name;
    EXPECT_EQ(m.tool.name.find(std::string("GYRO:navigator (") + g.name + "; "), 0u) << m.tool.name;
  }
  // A figure given over the preset is the one used, and the name says the bias.
  const NavigatorParameters own = navigator_dump({{"gyro_bias_dph", "2.5"}});
  const NavigatorModel m = navigator_tool_code(own);
  EXPECT_EQ(term_magnitude(m.tool, "GXYZ-GD"), 2.5);
  EXPECT_NEAR(term_magnitude(m.tool, "GXYZ-GD") * kNavDegPerHour, strapdown::parse_parameters(own).gyro_bias_sd, 1e-15);
  EXPECT_NE(m.tool.name.find("tactical 2.5 deg/h"), std::string::npos) << m.tool.name;
}

TEST(NavigatorToolCode, InitialisationIsHowTheNavigatorAligned) {
  // The magnetometer (the default): the heading's model error and the string's axial magnetisation
  // at its worst, 0.3 uT of the horizontal field.
  const NavigatorModel magnetic = navigator_tool_code(navigator_dump(), 50, 60);
  EXPECT_NEAR(term_magnitude(magnetic.tool, "EXT-REF"), std::hypot(0.05, 0.3 / 25.0 / kNavDeg), 1e-12);
  EXPECT_EQ(magnetic.initialisation, "magnetic azimuth");
  // The navigator's own field where it was given, else the survey's reference.
  const NavigatorModel given_field = navigator_tool_code(navigator_dump({{"field_uT", "48.4"}, {"dip_deg", "45.5"}}), 50, 60);
  EXPECT_NEAR(term_magnitude(given_field.tool, "EXT-REF"), std::hypot(0.05, 0.3 / (48.4 * std::cos(45.5 * kNavDeg)) / kNavDeg),
              1e-12);
  // A given azimuth: its sigma, 0 included (the frame is then the given azimuth's own).
  const NavigatorModel given = navigator_tool_code(navigator_dump({{"initial_azimuth_deg", "30"}, {"initial_azimuth_sd_deg", "0.3"}}));
  EXPECT_EQ(term_magnitude(given.tool, "EXT-REF"), 0.3);
  EXPECT_EQ(given.tool.gyro.initialisation, GyroInitialisation::Reference);
  EXPECT_FALSE(needs_latitude(given.tool));
  EXPECT_EQ(term_magnitude(navigator_tool_code(navigator_dump({{"initial_azimuth_deg", "30"}})).tool, "EXT-REF"), 0.0);
  // Neither a magnetometer nor an azimuth: relative to the alignment.
  const NavigatorModel relative = navigator_tool_code(navigator_dump({{"use_magnetometer", "0"}}));
  EXPECT_EQ(term_magnitude(relative.tool, "EXT-REF"), 0.0);
  EXPECT_EQ(relative.initialisation, "relative azimuth");
  // A gyrocompass: the triad's bias in full, its noise averaged over the alignment, at the
  // navigator's latitude.
  const NavigatorModel compass =
      navigator_tool_code(navigator_dump({{"gyrocompass", "1"}, {"imu_grade", "navigation"}, {"latitude_deg", "58"}, {"align_s", "120"}}));
  EXPECT_EQ(compass.tool.gyro.initialisation, GyroInitialisation::Gyrocompass);
  EXPECT_TRUE(needs_latitude(compass.tool));
  EXPECT_EQ(compass.latitude_deg, 58);
  EXPECT_EQ(term_magnitude(compass.tool, "GXYZ-XYB1"), 0.01);
  EXPECT_EQ(term_magnitude(compass.tool, "GXYZ-ZB"), 0.01);
  EXPECT_NEAR(term_magnitude(compass.tool, "GXYZ-XYRN"), 0.002 / std::sqrt(120.0 / 3600.0), 1e-15);
  EXPECT_TRUE(std::isnan(term_magnitude(compass.tool, "EXT-REF")));
  EXPECT_TRUE(has_gyro_terms(compass.tool));
}

TEST(NavigatorToolCode, NamesFitTheSurveyMessage) {
  for (const ImuGradeFigures& g : kImuGrades)
    for (const auto& how : std::vector<std::vector<std::pair<std::string, std::string>>>{
             {}, {{"gyrocompass", "1"}}, {{"initial_azimuth_deg", "1"}, {"initial_azimuth_sd_deg", "12.345"}},
             {{"use_magnetometer", "0"}}, {{"gyro_bias_dph", "12345.678"}, {"mag_axial_bias_uT", "99"}}}) {
      auto given = how;
      given.emplace_back("imu_grade", g.name);
      const std::string name = navigator_tool_code(navigator_dump(given)).tool.name;
      EXPECT_LE(name.size(), 63u) << name;
      EXPECT_EQ(name.rfind("GYRO:navigator (", 0), 0u) << name;
    }
}

TEST(NavigatorToolCode, RefusesParametersThatAreNotTheNavigators) {
  NavigatorParameters p = navigator_dump();
  p.erase("imu_grade");
  EXPECT_THROW(navigator_tool_code(p), std::invalid_argument);
  EXPECT_THROW(navigator_tool_code(navigator_dump({{"imu_grade", "consumer"}})), std::invalid_argument);
  EXPECT_THROW(navigator_tool_code(navigator_dump({{"gyro_bias_dph", "fast"}})), std::invalid_argument);
}

// A horizontal well drilled east for four hours: the run's azimuth sigma from the navigator's own
// terms is the given azimuth's, the drift b t and the random walk q sqrt(t) added in quadrature.
TEST(NavigatorToolCode, AzimuthSigmaGrowsWithTheNavigatorsDriftAndRandomWalk) {
  NavigatorModel m = navigator_tool_code(navigator_dump({{"initial_azimuth_deg", "90"}, {"initial_azimuth_sd_deg", "0.2"}}));
  std::vector<Term> gyro;
  for (const Term& t : m.tool.terms)
    if (t.code == "EXT-REF" || t.code == "GXYZ-GD" || t.code == "GXYZ-GRW") gyro.push_back(t);
  ASSERT_EQ(gyro.size(), 3u);
  m.tool.terms = gyro;
  std::vector<Station> stations;
  for (int k = 0; k <= 8; ++k) stations.push_back({1000.0 + 30 * k, 90, 90, 90, 800, 1800.0 * k});
  const Result r = propagate(stations, m.tool, Field{});
  for (std::size_t k = 0; k < stations.size(); ++k) {
    const double hours = 0.5 * static_cast<double>(k);
    const double want_deg2 = 0.2 * 0.2 + std::pow(1.0 * hours, 2) + 0.05 * 0.05 * hours;  // tactical: 1 deg/h, 0.05 deg/rt-h
    EXPECT_NEAR(r.angle_variance[k](1) / (kNavDeg * kNavDeg), want_deg2, 1e-9 * (1 + want_deg2)) << k;
    EXPECT_NEAR(r.angle_variance[k](0), 0.0, 1e-18) << k;  // a triad's drift turns the azimuth only
  }
}

}  // namespace
}  // namespace plumb::survey::iscwsa
