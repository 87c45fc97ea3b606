// The sensor error model measured = (I + diag(scale) + misalignment) true + bias
// + bias_temp (temp - 25), the temperature ramp, and the vibration and shocks added to f.
#include <cmath>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/platform.hpp"

namespace plumb::sim {
namespace {

// 60 rpm at 100 Hz for 10 s: ten whole revolutions of 100 equally spaced samples, so the radial
// sinusoids sum to zero (up to round-off) and averages show the constant terms only.
Scenario whole_revolutions() {
  Scenario sc;
  sc.g = 9.81;
  sc.inclination_deg = 20;
  sc.azimuth_deg = 60;
  sc.rotation.rpm = 60;
  sc.sample_rate_hz = 100;
  sc.duration_s = 10;
  return sc;
}

Eigen::Vector3d mean_f(const std::vector<Sample>& s) {
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (const auto& x : s) m += x.f;
  return m / static_cast<double>(s.size());
}
Eigen::Vector3d mean_b(const std::vector<Sample>& s) {
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (const auto& x : s) m += x.b;
  return m / static_cast<double>(s.size());
}

TEST(SensorErrors, BiasAndScaleShowInAveragesOverWholeRevolutions) {
  Scenario sc = whole_revolutions();
  sc.accel_errors.bias = {0.05, -0.03, 0.02};
  sc.accel_errors.scale = {0.01, 0.02, -0.004};
  sc.mag_errors.bias = {1.5, -0.7, 0.4};
  sc.mag_errors.scale = {0.0, 0.0, 0.003};
  const auto s = PlatformSimulator(sc).run();
  const double gz = sc.g * std::cos(sc.inclination_deg * kDeg);
  const Eigen::Vector3d expect_f(0.05, -0.03, 0.02 + (1 - 0.004) * -gz);
  EXPECT_LT((mean_f(s) - expect_f).norm(), 1e-12);
  const double bz = field_tool(sc.inclination_deg * kDeg, sc.azimuth_deg * kDeg, 0, sc.total_b, sc.dip_deg * kDeg).z();
  const Eigen::Vector3d expect_b(1.5, -0.7, 0.4 + 1.003 * bz);
  EXPECT_LT((mean_b(s) - expect_b).norm(), 1e-10);
  // The scale factor stretches the radial amplitude: max of fx over a revolution is (1+s) g sinI.
  double max_fx = -1e9;
  for (const auto& x : s) max_fx = std::max(max_fx, x.f.x());
  EXPECT_NEAR(max_fx, 0.05 + 1.01 * sc.g * std::sin(sc.inclination_deg * kDeg), 1e-9);
}

TEST(SensorErrors, MisalignmentCouplesAxes) {
  Scenario sc = whole_revolutions();
  sc.rotation.rpm = 0;
  sc.inclination_deg = 90;  // horizontal tool at toolface 0: f = (g, 0, 0)
  sc.accel_errors.misalignment(1, 0) = 0.01;
  sc.accel_errors.misalignment(2, 0) = -0.02;
  sc.duration_s = 0.1;
  for (const auto& x : PlatformSimulator(sc).run()) {
    EXPECT_NEAR(x.f.x(), sc.g, 1e-12);
    EXPECT_NEAR(x.f.y(), 0.01 * sc.g, 1e-12);
    EXPECT_NEAR(x.f.z(), -0.02 * sc.g, 1e-12);
  }
}

TEST(SensorErrors, TemperatureRampsLinearlyAndDrivesBiasDrift) {
  Scenario sc = whole_revolutions();
  sc.temp_start_c = 25;
  sc.temp_end_c = 125;
  sc.accel_errors.bias_temp = {1e-3, 0, -2e-3};
  sc.mag_errors.bias_temp = {0, 0.01, 0};
  Scenario clean = sc;
  clean.accel_errors = {};
  clean.mag_errors = {};
  const auto s = PlatformSimulator(sc).run();
  const auto c = PlatformSimulator(clean).run();
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double expect_temp = 25 + 100 * s[k].t / sc.duration_s;
    ASSERT_NEAR(s[k].temp_c, expect_temp, 1e-9);
    const double dtemp = s[k].temp_c - 25;
    ASSERT_LT((s[k].f - c[k].f - Eigen::Vector3d(1e-3, 0, -2e-3) * dtemp).norm(), 1e-12);
    ASSERT_LT((s[k].b - c[k].b - Eigen::Vector3d(0, 0.01, 0) * dtemp).norm(), 1e-12);
  }
  EXPECT_EQ(s.front().temp_c, 25.0);
}

TEST(SensorErrors, GyroErrors) {
  Scenario sc = whole_revolutions();
  sc.gyro_errors.bias = {1e-3, 2e-3, -1e-3};
  sc.gyro_errors.scale = {0, 0, 0.01};
  sc.earth_rate = 0;
  for (const auto& x : PlatformSimulator(sc).run())
    ASSERT_LT((x.w - Eigen::Vector3d(1e-3, 2e-3, -1e-3 + 1.01 * 2 * kPi)).norm(), 1e-12);
}

TEST(Vibration, LateralRmsAndNoAxialPart) {
  Scenario sc = whole_revolutions();
  sc.duration_s = 100;
  sc.vibration.lateral_rms = 0.8;
  sc.vibration.frequency_hz = 12;
  Scenario clean = sc;
  clean.vibration = {};
  const auto s = PlatformSimulator(sc).run();
  const auto c = PlatformSimulator(clean).run();
  double sx = 0, sy = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Eigen::Vector3d d = s[k].f - c[k].f;
    sx += d.x() * d.x();
    sy += d.y() * d.y();
    ASSERT_EQ(d.z(), 0.0);
    ASSERT_LE(std::hypot(d.x(), d.y()), 2 * 4 * 0.8 * std::sqrt(2.0 / 4));  // all tones in phase
  }
  // Tones f/6 = 2 Hz apart: their cross terms average to ~1/(pi df T) ~ 2e-3 over 100 s.
  const double n = static_cast<double>(s.size());
  EXPECT_NEAR(std::sqrt(sx / n), 0.8, 0.02 * 0.8);
  EXPECT_NEAR(std::sqrt(sy / n), 0.8, 0.02 * 0.8);
}

TEST(Vibration, ShocksArePoissonHalfSinesWithinThePeak) {
  Scenario sc = whole_revolutions();
  sc.duration_s = 100;
  sc.vibration.shock_rate_hz = 0.5;
  sc.vibration.shock_peak = 30;
  Scenario clean = sc;
  clean.vibration = {};
  const auto s = PlatformSimulator(sc).run();
  const auto c = PlatformSimulator(clean).run();
  int shocks = 0;
  bool in_shock = false;
  double peak = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Eigen::Vector3d d = s[k].f - c[k].f;
    ASSERT_EQ(d.z(), 0.0);
    const double lateral = std::hypot(d.x(), d.y());
    ASSERT_LE(lateral, 30 * (1 + 1e-12));
    peak = std::max(peak, lateral);
    if (lateral > 0 && !in_shock) ++shocks;
    in_shock = lateral > 0;
  }
  // Poisson with mean 50: five standard deviations either side.
  EXPECT_NEAR(shocks, 50, 5 * std::sqrt(50.0));
  // A shock spans two sample periods, so its two samples sit at phases u and u + 1/2 of the half
  // sine: both stay below 0.9 of the peak for 21 % of the u only, so over ~50 shocks the largest
  // sample is above 0.9 of the peak except with probability 0.21^50.
  EXPECT_GT(peak, 0.9 * 30);
}

}  // namespace
}  // namespace plumb::sim
