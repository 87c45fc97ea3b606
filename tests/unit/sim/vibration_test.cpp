// The simulators' broadband vibration (Vibration::band_hz; the default few tones are tested with the
// platform in sensor_errors_test.cpp): the stated rms, and where its energy lies (a discrete Fourier
// transform of 10 s at 200 Hz: 0.1 Hz bins).
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/sim/vibration.hpp"

namespace plumb::sim {
namespace {

struct Record {
  double rms[2] = {0, 0}, mean[2] = {0, 0};
};

Record record(const Vibration& v, std::uint64_t seed, double seconds = 100, double rate_hz = 500) {
  std::mt19937_64 rng(seed);
  const VibrationTones tones(v, rng);
  Record r;
  const auto n = static_cast<long>(seconds * rate_hz);
  for (long k = 0; k < n; ++k) {
    const Eigen::Vector2d x = tones.at(static_cast<double>(k) / rate_hz);
    for (int axis = 0; axis < 2; ++axis) {
      r.mean[axis] += x[axis] / static_cast<double>(n);
      r.rms[axis] += x[axis] * x[axis] / static_cast<double>(n);
    }
  }
  for (double& x : r.rms) x = std::sqrt(x);
  return r;
}

TEST(BroadbandVibration, CarriesTheStatedRms) {
  Vibration v;
  v.lateral_rms = 3.0;
  v.frequency_hz = 24;
  v.band_hz = 32;
  const Record r = record(v, 7);
  for (int axis = 0; axis < 2; ++axis) {
    EXPECT_NEAR(r.rms[axis], 3.0, 0.03 * 3.0) << axis;
    EXPECT_NEAR(r.mean[axis], 0.0, 0.02) << axis;
  }
}

// The share of the x axis's energy in [lo, hi) Hz.
double energy_share(const Vibration& v, std::uint64_t seed, double lo, double hi) {
  constexpr int kN = 2000;
  constexpr double kRate = 200;
  std::mt19937_64 rng(seed);
  const VibrationTones tones(v, rng);
  std::vector<double> x(kN);
  for (int k = 0; k < kN; ++k) x[k] = tones.at(k / kRate).x();
  double in = 0, all = 0;
  for (int bin = 1; bin < kN / 2; ++bin) {
    std::complex<double> sum = 0;
    for (int k = 0; k < kN; ++k) sum += x[k] * std::polar(1.0, -2.0 * std::numbers::pi * bin * k / kN);
    const double power = std::norm(sum), f = bin * kRate / kN;
    all += power;
    if (f >= lo && f < hi) in += power;
  }
  return in / all;
}

TEST(BroadbandVibration, SpreadsOverItsBand) {
  Vibration v;
  v.lateral_rms = 3.0;
  v.frequency_hz = 24;
  // The default tones sit at 18, 22, 26 and 30 Hz: nothing below 16 Hz.
  EXPECT_LT(energy_share(v, 3, 0, 16), 0.03);
  // Over 8-40 Hz a quarter of the band lies below 16 Hz (64 tones drawn across it: 0.25 +- 0.05),
  // and nothing outside the band but the transform's leakage.
  v.band_hz = 32;
  EXPECT_NEAR(energy_share(v, 3, 8, 16), 0.25, 0.1);
  EXPECT_GT(energy_share(v, 3, 7.5, 40.5), 0.97);
}

TEST(BroadbandVibration, ABandReachingZeroIsRefused) {
  Vibration v;
  v.frequency_hz = 24;
  v.band_hz = 32;
  EXPECT_EQ(vibration_problem(v), "");
  EXPECT_EQ(describe(v), "0 m/s2 rms over 8-40 Hz");
  v.band_hz = 48;
  EXPECT_NE(vibration_problem(v).find("vibration band"), std::string::npos);
  v.band_hz = -1;
  EXPECT_NE(vibration_problem(v).find("vibration band"), std::string::npos);
}

}  // namespace
}  // namespace plumb::sim
