// The platform-angle tracker on synthetic fields with known motion.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "plumb/core/attitude.hpp"
#include "plumb/windowed/platform_angle.hpp"

namespace plumb::windowed {
namespace {

// Radial field of amplitude r whose magnetic toolface follows angle(t), plus white noise.
WindowData field_window(const std::function<double(double)>& angle, double r, double sigma, int n = 1000,
                        double fs = 100) {
  WindowData w;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0, sigma);
  for (int k = 0; k < n; ++k) {
    const double t = k / fs, m = angle(t);
    w.t.push_back(t);
    w.bx.push_back(r * std::cos(m) + noise(rng));
    w.by.push_back(-r * std::sin(m) + noise(rng));  // M = atan2(-By, Bx)
    w.bz.push_back(30 + noise(rng));
    w.gx.push_back(0), w.gy.push_back(0), w.gz.push_back(9.8);
  }
  w.nominal_dt = 1 / fs;
  return w;
}

TEST(PlatformAngle, ConstantSpeedIsALineWithTheRightRate) {
  const double rate = 2 * kPi * 123.0 / 60;
  const WindowData w = field_window([&](double t) { return 0.3 + rate * t; }, 34, 0.0);
  const PlatformAngle a = track_platform_angle(w);
  ASSERT_TRUE(a.ok) << a.reason;
  EXPECT_EQ(a.model_degree, 1);
  EXPECT_NEAR(a.rpm(), 123.0, 1e-6);
  EXPECT_NEAR(a.revolutions(), 123.0 / 60 * 9.99, 1e-6);
  for (std::size_t k = 0; k < w.size(); ++k) EXPECT_NEAR(std::remainder(a.phase[k] - (0.3 + rate * w.t[k]), 2 * kPi), 0, 1e-9);
}

TEST(PlatformAngle, NoiseVarianceIsMeasuredFromTheData) {
  const double r = 34, sigma = 2.4;  // SNR_m 20 dB: toolface noise sigma/r per sample
  const WindowData w = field_window([](double t) { return 2 * kPi * t; }, r, sigma);
  const PlatformAngle a = track_platform_angle(w);
  ASSERT_TRUE(a.ok);
  const double expected = (sigma / r) * (sigma / r);
  // Relative sd of a variance estimate from 1000 correlated second differences is ~8 %.
  EXPECT_NEAR(a.phase_noise_var, expected, 0.3 * expected);
  EXPECT_EQ(a.model_degree, 1);
  // The fitted line averages the noise: its error is ~ sigma/r / sqrt(N) ~ 2e-3 rad.
  double worst = 0;
  for (std::size_t k = 0; k < w.size(); ++k) worst = std::max(worst, std::abs(a.phase[k] - 2 * kPi * w.t[k]));
  EXPECT_LT(worst, 5 * 2 * (sigma / r) / std::sqrt(1000.0));
}

TEST(PlatformAngle, RampNeedsAQuadratic) {
  const double acc = 2 * kPi * 1.2;  // rad/s^2
  const WindowData w = field_window([&](double t) { return 0.5 * acc * t * t; }, 34, 0.5);
  const PlatformAngle a = track_platform_angle(w);
  ASSERT_TRUE(a.ok);
  EXPECT_EQ(a.model_degree, 2);
}

TEST(PlatformAngle, StickSlipFallsBackToTheLocalSmoother) {
  const double mean = 2 * kPi, swing = 2 * kPi;  // speed swings 0 .. 2 x mean, period 2 s
  const auto angle = [&](double t) { return mean * t - swing / kPi * std::cos(kPi * t); };
  const WindowData w = field_window(angle, 34, 0.5);
  const PlatformAngle a = track_platform_angle(w);
  ASSERT_TRUE(a.ok);
  EXPECT_EQ(a.model_degree, 0);
  double ss = 0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    const double d = a.phase[k] - a.phase[0] - (angle(w.t[k]) - angle(0));
    ss += d * d;
  }
  // Smoothing reduces the per-sample toolface noise (0.5/34 rad) by about three.
  EXPECT_LT(std::sqrt(ss / w.size()), 0.5 * 0.5 / 34);
}

TEST(PlatformAngle, StillPlatformHasNoSpan) {
  const WindowData w = field_window([](double) { return 1.0; }, 34, 2.4);
  const PlatformAngle a = track_platform_angle(w);
  ASSERT_TRUE(a.ok);
  // Half-second block means of a 4-degree noise: a few tenths of a degree apart.
  EXPECT_LT(a.block_span_rad / kDeg, 3.0);
}

TEST(PlatformAngle, NoRadialFieldIsReported) {
  const WindowData w = field_window([](double) { return 0.0; }, 0, 0);
  const PlatformAngle a = track_platform_angle(w);
  EXPECT_FALSE(a.ok);
  EXPECT_FALSE(a.reason.empty());
}

TEST(LocalQuadratic, ReproducesAQuadraticExactly) {
  std::vector<double> y;
  for (int k = 0; k < 50; ++k) y.push_back(1 + 0.5 * k - 0.03 * k * k);
  const auto s = smooth_local_quadratic(y, 6);
  for (std::size_t k = 0; k < y.size(); ++k) EXPECT_NEAR(s[k], y[k], 1e-9);
}

}  // namespace
}  // namespace plumb::windowed
