// White noise: its standard deviation follows the SNR definition of docs/conventions.md (computed
// here independently from the field geometry), it is zero-mean and reproducible for a seed.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/platform.hpp"

namespace plumb::sim {
namespace {

struct Residuals {
  std::vector<double> accel, mag, gyro;
};

// The simulator always draws the same random numbers, so the noiseless run of the same
// scenario is the exact signal and the difference is the noise alone.
Residuals noise_of(Scenario noisy) {
  Scenario clean = noisy;
  clean.noise = Noise{};
  PlatformSimulator a(noisy), b(clean);
  Residuals r;
  while (!a.done()) {
    const Sample n = a.next(), c = b.next();
    for (int i = 0; i < 3; ++i) {
      r.accel.push_back(n.f[i] - c.f[i]);
      r.mag.push_back(n.b[i] - c.b[i]);
      r.gyro.push_back(n.w[i] - c.w[i]);
    }
  }
  return r;
}

// n * s^2 / sigma^2 is chi-square with n degrees of freedom (mean known to be zero): its mean is
// n and its standard deviation sqrt(2n). Five standard deviations: a false alarm is ~1e-6.
void expect_variance(const std::vector<double>& x, double sigma, const char* what) {
  ASSERT_GT(sigma, 0);
  double sum2 = 0, sum = 0;
  for (double v : x) {
    sum2 += v * v;
    sum += v;
  }
  const double n = static_cast<double>(x.size());
  const double ratio = sum2 / n / (sigma * sigma);
  EXPECT_NEAR(ratio, 1.0, 5 * std::sqrt(2.0 / n)) << what;
  // The mean of n samples has standard deviation sigma / sqrt(n).
  EXPECT_NEAR(sum / n, 0.0, 5 * sigma / std::sqrt(n)) << what;
}

TEST(PlatformNoise, SigmaFollowsTheSnrDefinition) {
  for (double inc : {0.5, 2.0, 30.0})
    for (double snr_a : {10.0, 20.0}) {
      Scenario sc = Scenario::reference(inc, 130.0, 60.0, snr_a, 7);
      sc.duration_s = 50;  // 15000 values per triad
      // Radial components: g sinI for gravity; for the field, the axial part is
      // Bz = B (sinI cosA cos(dip) + cosI sin(dip)) and the rest of |B|^2 is radial.
      const double radial_g = 10.0 * std::sin(inc * kDeg);
      const double bz = 48.4 * (std::sin(inc * kDeg) * std::cos(130 * kDeg) * std::cos(45.5 * kDeg) +
                                std::cos(inc * kDeg) * std::sin(45.5 * kDeg));
      const double radial_b2 = 48.4 * 48.4 - bz * bz;
      const double sigma_a = radial_g / std::sqrt(2.0) / std::pow(10.0, snr_a / 20);
      const double sigma_m = std::sqrt(radial_b2 / 2.0) / std::pow(10.0, 20.0 / 20);
      EXPECT_NEAR(sc.sigma_accel(), sigma_a, 1e-12 * sigma_a);
      EXPECT_NEAR(sc.sigma_mag(), sigma_m, 1e-12 * sigma_m);
      const Residuals r = noise_of(sc);
      expect_variance(r.accel, sigma_a, "accelerometer");
      expect_variance(r.mag, sigma_m, "magnetometer");
    }
}

TEST(PlatformNoise, SigmaGivenDirectlyWinsOverSnr) {
  Scenario sc = Scenario::reference(1.0, 0.0, 60.0, 10.0, 3);
  sc.noise.sigma_accel = 0.02;
  sc.noise.sigma_mag = 0.3;
  sc.noise.sigma_gyro = 1e-3;
  EXPECT_EQ(sc.sigma_accel(), 0.02);
  EXPECT_EQ(sc.sigma_mag(), 0.3);
  const Residuals r = noise_of(sc);
  expect_variance(r.accel, 0.02, "accelerometer");
  expect_variance(r.mag, 0.3, "magnetometer");
  expect_variance(r.gyro, 1e-3, "gyro");
}

TEST(PlatformNoise, NoNoiseWithoutSigmaOrSnr) {
  Scenario sc;
  EXPECT_EQ(sc.sigma_accel(), 0.0);
  EXPECT_EQ(sc.sigma_mag(), 0.0);
}

TEST(PlatformNoise, NoiseIsWhite) {
  // Lag-one correlation of white noise is ~N(0, 1/n).
  Scenario sc = Scenario::reference(2.0, 10.0, 60.0, 10.0, 11);
  sc.duration_s = 100;
  const Residuals r = noise_of(sc);
  for (int axis = 0; axis < 3; ++axis) {
    double c0 = 0, c1 = 0;
    std::size_t n = 0;
    for (std::size_t k = axis + 3; k < r.accel.size(); k += 3, ++n) {
      c0 += r.accel[k] * r.accel[k];
      c1 += r.accel[k] * r.accel[k - 3];
    }
    EXPECT_NEAR(c1 / c0, 0.0, 5.0 / std::sqrt(static_cast<double>(n)));
  }
}

bool same(const Sample& a, const Sample& b) {
  return a.seq == b.seq && a.t == b.t && a.f == b.f && a.b == b.b && a.w == b.w && a.temp_c == b.temp_c &&
         a.flags == b.flags;
}

Scenario busy_scenario(std::uint64_t seed) {
  Scenario sc = Scenario::reference(1.0, 45.0, 60.0, 10.0, seed);
  sc.noise.sigma_gyro = 1e-3;
  sc.vibration.lateral_rms = 0.5;
  sc.vibration.shock_rate_hz = 2;
  sc.vibration.shock_peak = 20;
  return sc;
}

TEST(PlatformNoise, DeterministicForASeedDifferentAcrossSeeds) {
  const auto a = PlatformSimulator(busy_scenario(5)).run();
  const auto b = PlatformSimulator(busy_scenario(5)).run();
  const auto c = PlatformSimulator(busy_scenario(6)).run();
  ASSERT_EQ(a.size(), b.size());
  std::size_t equal_to_other_seed = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_TRUE(same(a[k], b[k])) << k;
    if (a[k].f == c[k].f || a[k].b == c[k].b) ++equal_to_other_seed;
  }
  EXPECT_EQ(equal_to_other_seed, 0u);
}

}  // namespace
}  // namespace plumb::sim
