// The whole navigator on a still tool: it keeps its attitude, finds the gyro biases within its own
// sigma, and gyrocompasses with error-free gyros.
#include <cmath>

#include <gtest/gtest.h>

#include "plumb/strapdown/parameters.hpp"
#include "strapdown_test_support.hpp"

namespace plumb::strapdown::test {
namespace {

constexpr double kDegPerHour = kDeg / 3600.0;

NavigatorConfig tactical_config(double latitude_deg) {
  return parse_parameters({{"latitude_deg", std::to_string(latitude_deg)}, {"imu_grade", "tactical"},
                           {"gravity", "9.80665"}, {"align_s", "30"}});
}

TEST(StrapdownStill, KeepsAttitudeAndFindsGyroBiases) {
  StillTool tool;
  tool.duration_s = 600;
  tool.gyro_bias = Eigen::Vector3d(0.8, -1.2, 0.5) * kDegPerHour;
  tool.accel_bias = Eigen::Vector3d(2e-3, -1e-3, 3e-3);
  tool.sigma_gyro = 0.05 * kDeg / 60.0 / std::sqrt(0.01);  // tactical ARW at 100 Hz
  tool.sigma_accel = 0.03 / 60.0 / std::sqrt(0.01);
  tool.sigma_mag = 0.1;
  Navigator nav(tactical_config(tool.latitude_deg));
  const auto rows = run(nav, tool.samples());
  ASSERT_TRUE(nav.aligned());
  ASSERT_FALSE(rows.empty());
  const StateMatrix& p = nav.covariance();
  // Still, a gyro's bias and its response to the (constant) specific force are one sum: that sum is
  // what the stops find, with its sigma from the covariance of both.
  const Eigen::Matrix<double, 3, 2> g_of_f = gyro_g_matrix(-tool.c_nb() * Eigen::Vector3d(0, 0, tool.g));
  const Eigen::Vector3d found = nav.gyro_bias() + g_of_f * nav.gyro_g();
  Eigen::Matrix<double, 3, kStates> h = Eigen::Matrix<double, 3, kStates>::Zero();
  h.block<3, 3>(0, index::kGyroBias).setIdentity();
  h.block<3, 2>(0, index::kGyroG) = g_of_f;
  const Eigen::Matrix3d p_found = h * p * h.transpose();
  for (int i = 0; i < 3; ++i) {
    const double sd = std::sqrt(p_found(i, i));
    EXPECT_LT(std::abs(found[i] - tool.gyro_bias[i]), 3.5 * sd) << "axis " << i;
    // Observable: far below the prior of 1 deg/h.
    EXPECT_LT(sd, 0.3 * kDegPerHour) << "axis " << i;
  }
  const Eigen::Vector3d att = attitude_error(nav.state().q, tool.c_nb());
  for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(att[i]), 3.5 * std::sqrt(p(i, i)) + 1e-6);
  const Estimate& last = rows.back();
  EXPECT_TRUE(last.valid);
  EXPECT_NEAR(last.inclination_deg, tool.inclination_deg, 3.5 * last.inclination_sd_deg + 1e-4);
  EXPECT_NEAR(wrap_deg_180(last.azimuth_deg - tool.azimuth_deg), 0.0, 3.5 * last.azimuth_sd_deg + 1e-4);
  EXPECT_NEAR(wrap_deg_180(last.gravity_toolface_deg - tool.toolface_deg), 0.0, 3.5 * last.toolface_sd_deg + 1e-4);
  ASSERT_TRUE(last.navigation.has_value());
  EXPECT_TRUE(last.navigation->still);
  EXPECT_EQ(last.navigation->azimuth_reference, "magnetic");
  for (double v : last.navigation->position_m) EXPECT_LT(std::abs(v), 1e-3);
}

// Error-free gyros see only the earth rate: gyrocompassing finds true north. What is left comes
// from the accelerometer noise through the tilt: the earth rate's down part leaks into the
// horizontal by the tilt error, dA ~ tan(L) d(tilt), with d(tilt) ~ sigma_a / (g sqrt(N)).
TEST(StrapdownStill, GyrocompassFindsNorthWithErrorFreeGyros) {
  for (const double azimuth : {0.0, 75.0, 200.0, 310.0}) {
    StillTool tool;
    tool.azimuth_deg = azimuth;
    tool.duration_s = 40;
    tool.sigma_accel = 0.005;
    tool.magnetometer = false;
    auto config = tactical_config(tool.latitude_deg);
    config.gyrocompass = true;
    config.use_magnetometer = false;
    // The filter is told the truth about these gyros: no bias, no noise to speak of.
    config.gyro_bias_sd = 1e-4 * kDegPerHour;
    config.gyro_arw = 1e-5 * kDeg / 60.0;
    Navigator nav(config);
    const auto rows = run(nav, tool.samples());
    ASSERT_FALSE(rows.empty());
    const Estimate& last = rows.back();
    ASSERT_TRUE(last.valid && last.azimuth_valid);
    const double n = 30.0 * tool.rate_hz;
    const double tilt_sd = tool.sigma_accel / (tool.g * std::sqrt(n));
    const double bound_deg = 5.0 * tilt_sd * (1.0 + std::tan(tool.latitude_deg * kDeg)) / kDeg / std::sin(tool.inclination_deg * kDeg) + 1e-3;
    EXPECT_LT(std::abs(wrap_deg_180(last.azimuth_deg - azimuth)), bound_deg) << "azimuth " << azimuth;
    EXPECT_EQ(last.navigation->azimuth_reference, "true");
  }
}

// No magnetometer and an initial azimuth: the azimuth is relative and its sigma grows as the gyro
// bias allows (it is not reset by anything).
TEST(StrapdownStill, InitialAzimuthWithoutMagnetometerIsRelative) {
  StillTool tool;
  tool.duration_s = 120;
  tool.magnetometer = false;
  tool.sigma_accel = 0.005;
  tool.sigma_gyro = 0.05 * kDeg / 60.0 / std::sqrt(0.01);
  auto config = tactical_config(tool.latitude_deg);
  config.use_magnetometer = false;
  config.initial_azimuth = tool.azimuth_deg * kDeg;
  Navigator nav(config);
  const auto rows = run(nav, tool.samples());
  ASSERT_GE(rows.size(), 2u);
  const Estimate& last = rows.back();
  EXPECT_EQ(last.navigation->azimuth_reference, "relative");
  EXPECT_NEAR(wrap_deg_180(last.azimuth_deg - tool.azimuth_deg), 0.0, 3.5 * last.azimuth_sd_deg + 1e-4);
}

}  // namespace
}  // namespace plumb::strapdown::test
