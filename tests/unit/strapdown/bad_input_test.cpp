// Bad input: counted and reported, never a crash, a NaN or a silent wrong answer.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "plumb/strapdown/parameters.hpp"
#include "strapdown_test_support.hpp"

namespace plumb::strapdown::test {
namespace {

NavigatorConfig config() { return parse_parameters({{"latitude_deg", "35"}, {"gravity", "9.80665"}}); }

StillTool quiet_tool(double duration_s) {
  StillTool tool;
  tool.duration_s = duration_s;
  tool.sigma_accel = 0.005;
  tool.sigma_gyro = 1e-4;
  tool.sigma_mag = 0.05;
  return tool;
}

void expect_all_finite(const std::vector<Estimate>& rows) {
  for (const Estimate& e : rows) EXPECT_TRUE(e.all_finite()) << "t " << e.t_end;
}

TEST(StrapdownBadInput, MissingGyrosSayWhy) {
  auto samples = quiet_tool(20).samples();
  for (Sample& s : samples) s.flags &= ~flags::kHasGyro;
  Navigator nav(config());
  const auto rows = run(nav, samples);
  ASSERT_FALSE(rows.empty());
  for (const Estimate& e : rows) {
    EXPECT_FALSE(e.valid);
    EXPECT_NE(e.reason.find("gyros"), std::string::npos) << e.reason;
  }
  EXPECT_EQ(nav.counters().at("no_gyro"), samples.size());
  expect_all_finite(rows);
}

TEST(StrapdownBadInput, NeverStillNeverValid) {
  // A tool turning at 30 rpm from the first sample on.
  auto samples = quiet_tool(30).samples();
  for (Sample& s : samples) s.w.z() += 3.14;
  Navigator nav(config());
  const auto rows = run(nav, samples);
  ASSERT_GE(rows.size(), 25u);
  for (const Estimate& e : rows) {
    EXPECT_FALSE(e.valid);
    EXPECT_NE(e.reason.find("aligning"), std::string::npos) << e.reason;
  }
  EXPECT_EQ(nav.counters().at("still_periods"), 0u);
  EXPECT_EQ(nav.counters().at("invalid_rows"), rows.size());
  expect_all_finite(rows);
}

TEST(StrapdownBadInput, AccelerometersInG) {
  auto samples = quiet_tool(20).samples();
  for (Sample& s : samples) s.f /= 9.80665;
  Navigator nav(parse_parameters({{"latitude_deg", "35"}}));
  const auto rows = run(nav, samples);
  ASSERT_FALSE(rows.empty());
  EXPECT_FALSE(rows.back().valid);
  EXPECT_NE(rows.back().reason.find("g units"), std::string::npos) << rows.back().reason;
  EXPECT_GE(nav.counters().at("accel_in_g"), 1u);
}

TEST(StrapdownBadInput, RepeatedBackwardsNonFiniteSaturatedAndGaps) {
  auto clean = quiet_tool(60).samples();
  std::vector<Sample> samples;
  for (std::size_t k = 0; k < clean.size(); ++k) {
    Sample s = clean[k];
    if (k > 0 && k % 500 == 0) samples.push_back(clean[k - 1]);  // repeated time stamp
    if (k % 700 == 0 && k > 0) {
      Sample back = clean[k - 3];
      samples.push_back(back);  // time going backwards
    }
    if (k % 900 == 0) {
      Sample bad = s;
      bad.f.x() = std::numeric_limits<double>::quiet_NaN();
      bad.flags |= flags::kNotFinite;
      samples.push_back(bad);
      continue;
    }
    if (k % 1100 == 0) s.flags |= flags::kGyroSaturated;
    if (k > 3000 && k < 3200) continue;  // a 2 s gap
    samples.push_back(s);
  }
  Navigator nav(config());
  const auto rows = run(nav, samples);
  const auto& c = nav.counters();
  EXPECT_GT(c.at("repeated_time"), 0u);
  EXPECT_GT(c.at("time_backwards"), 0u);
  EXPECT_GT(c.at("non_finite"), 0u);
  EXPECT_GT(c.at("gyro_saturated"), 0u);
  EXPECT_EQ(c.at("gaps"), 1u);
  expect_all_finite(rows);
  ASSERT_TRUE(nav.aligned());
  bool gap_reported = false;
  for (const Estimate& e : rows) gap_reported = gap_reported || e.reason.find("gap") != std::string::npos;
  EXPECT_TRUE(gap_reported);
  // The still tool's attitude survives all of it.
  const Estimate& last = rows.back();
  EXPECT_TRUE(last.valid);
  EXPECT_NEAR(last.inclination_deg, 60.0, 0.05);
}

// A tool hanging upside down (I near 180 deg) is valid; azimuth and toolface are flagged.
TEST(StrapdownBadInput, UpsideDownAndVertical) {
  for (const double inc : {179.99, 0.0, 120.0}) {
    StillTool tool = quiet_tool(40);
    tool.inclination_deg = inc;
    Navigator nav(config());
    const auto rows = run(nav, tool.samples());
    ASSERT_FALSE(rows.empty());
    const Estimate& last = rows.back();
    EXPECT_TRUE(last.valid) << inc;
    EXPECT_NEAR(last.inclination_deg, inc, 0.05);
    EXPECT_EQ(last.azimuth_valid, std::sin(inc * kDeg) > std::sin(kMinInclinationForToolfaceDeg * kDeg)) << inc;
    expect_all_finite(rows);
  }
}

// Uneven time steps (jitter) and a gyro time offset are handled without error.
TEST(StrapdownBadInput, JitterAndGyroTimeOffset) {
  auto samples = quiet_tool(40).samples();
  for (std::size_t k = 0; k < samples.size(); ++k) samples[k].t += (k % 2 ? 0.003 : -0.002);
  auto cfg = config();
  cfg.gyro_time_offset_s = -0.02;
  Navigator nav(cfg);
  const auto rows = run(nav, samples);
  ASSERT_FALSE(rows.empty());
  EXPECT_TRUE(rows.back().valid);
  EXPECT_NEAR(rows.back().inclination_deg, 60.0, 0.05);
}

TEST(StrapdownParameters, UnknownAndBadValuesAreRefused) {
  EXPECT_THROW(parse_parameters({{"latitude", "35"}}), estimator::ParameterError);
  EXPECT_THROW(parse_parameters({{"latitude_deg", "95"}}), estimator::ParameterError);
  EXPECT_THROW(parse_parameters({{"output_rate_hz", "0"}}), estimator::ParameterError);
  EXPECT_THROW(parse_parameters({{"still_detector", "fast"}}), estimator::ParameterError);
  EXPECT_THROW(parse_parameters({{"imu_grade", "consumer"}}), estimator::ParameterError);
  EXPECT_THROW(parse_parameters({{"gyrocompass", "1"}, {"initial_azimuth_deg", "10"}}), estimator::ParameterError);
  const NavigatorConfig c = parse_parameters({});
  EXPECT_DOUBLE_EQ(c.output_rate_hz, 1.0);
  EXPECT_FALSE(c.gravity.has_value());
  for (const auto& spec : parameter_specs()) {
    EXPECT_FALSE(spec.description.empty()) << spec.name;
  }
}

}  // namespace
}  // namespace plumb::strapdown::test
