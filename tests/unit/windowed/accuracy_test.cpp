// The accuracy the README claims on the reference grid of docs/conventions.md, through the
// comparison library (so the numbers `plumb compare` prints are the ones tested). Monte Carlo: 4
// seeds x 36 azimuths = 144 records per case; an efficient estimator's RMS error then has a
// relative standard deviation of 1/sqrt(2 x 144) = 5.9 %, so 1.25 x the bound is a 4-sigma limit.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "plumb/compare/compare.hpp"
#include "plumb/core/attitude.hpp"

namespace plumb::compare {
namespace {

constexpr int kSeeds = 4;

const CompareResult& reference_grid() {
  static const CompareResult result = [] {
    CompareConfig config = CompareConfig::reference_grid();
    config.seeds = kSeeds;
    return run_compare(config);
  }();
  return result;
}

// The mean error at one azimuth over `seeds` records has standard deviation ~ rms / sqrt(seeds);
// the fitted sinA, cosA amplitudes of 36 such means then have sd ~ rms sqrt(2 / (36 seeds)).
double amplitude_sd(double rms, int valid) { return rms * std::sqrt(2.0 / valid); }

TEST(EstimatorAccuracy, ReferenceGridTable) {
  write_report(std::cout, reference_grid());
  EXPECT_EQ(reference_grid().cases.size(), 18u);
}

TEST(EstimatorAccuracy, CompensatedWithinCramerRaoBoundOnReferenceGrid) {
  for (const auto& c : reference_grid().cases) {
    const PluginCaseResult* p = c.find("compensated");
    ASSERT_NE(p, nullptr);
    SCOPED_TRACE(testing::Message() << "I " << c.inclination_deg << " rpm " << c.rpm << " SNRa " << c.snr_accel_db);
    EXPECT_EQ(p->valid, p->records);
    EXPECT_LE(p->rms_azimuth_error_deg, 1.25 * c.crb_azimuth_deg);
    EXPECT_LE(p->rms_inclination_error_deg, 1.25 * c.crb_inclination_deg);
  }
}

TEST(EstimatorAccuracy, CompensatedHasNoAzimuthDependentBias) {
  for (const auto& c : reference_grid().cases) {
    const PluginCaseResult* p = c.find("compensated");
    ASSERT_NE(p, nullptr);
    SCOPED_TRACE(testing::Message() << "I " << c.inclination_deg << " rpm " << c.rpm << " SNRa " << c.snr_accel_db);
    const double sd = amplitude_sd(c.crb_azimuth_deg, p->valid);
    EXPECT_LE(std::abs(p->bias_sin_deg), 4 * sd);
    EXPECT_LE(std::abs(p->bias_cos_deg), 4 * sd);
    EXPECT_LE(std::abs(p->bias_mean_deg), 4 * c.crb_azimuth_deg / std::sqrt(p->valid));
  }
}

// The small-angle ratio atan2(P1, -P2) = atan2(Bh sinA, cosI Bh cosA - sinI Bv): its error is
// close to sinI tan(dip) sinA, a sinusoid of azimuth with extremes at 90 and 270 degrees.
double small_angle_error_deg(double inc_deg, double az_deg, double dip_deg) {
  const double i = inc_deg * kDeg, a = az_deg * kDeg, d = dip_deg * kDeg;
  const double predicted = std::atan2(std::cos(d) * std::sin(a), std::cos(i) * std::cos(d) * std::cos(a) - std::sin(i) * std::sin(d));
  return wrap_deg_180(predicted / kDeg - az_deg);
}

TEST(EstimatorAccuracy, IntegralReproducesPapersFinding) {
  const double dip = 45.5;
  for (double snr : {10.0, 20.0}) {
    for (double rpm : {60.0, 120.0}) {
      double previous_amplitude = 0;
      for (double inc : {0.5, 1.0, 2.0}) {
        const CaseResult* c = nullptr;
        for (const auto& k : reference_grid().cases) {
          if (k.inclination_deg == inc && k.rpm == rpm && k.snr_accel_db == snr) c = &k;
        }
        ASSERT_NE(c, nullptr);
        const PluginCaseResult* p = c->find("integral");
        ASSERT_NE(p, nullptr);
        SCOPED_TRACE(testing::Message() << "I " << inc << " rpm " << rpm << " SNRa " << snr);
        ASSERT_EQ(p->valid, p->records);
        // The mean error per azimuth follows the derived formula within its Monte Carlo spread.
        double misfit2 = 0, noise2 = 0;
        for (const auto& pt : p->by_azimuth) {
          const double d = pt.mean_azimuth_error_deg - small_angle_error_deg(inc, pt.azimuth_deg, dip);
          misfit2 += d * d;
          noise2 += std::max(0.0, pt.rms_azimuth_error_deg * pt.rms_azimuth_error_deg -
                                      pt.mean_azimuth_error_deg * pt.mean_azimuth_error_deg);
        }
        const double n_az = static_cast<double>(p->by_azimuth.size());
        const double noise_of_mean = std::sqrt(noise2 / n_az / (kSeeds - 1));
        EXPECT_LE(std::sqrt(misfit2 / n_az), 1.5 * noise_of_mean);
        // A sinusoid of azimuth: the sinA term carries it, extremes at 90 and 270 degrees.
        const double expected = std::tan(dip * kDeg) * std::sin(inc * kDeg) / kDeg;
        const double sd = amplitude_sd(std::sqrt(noise2 / n_az), p->valid);
        EXPECT_NEAR(p->bias_sin_deg, expected, 4 * sd + 0.02 * expected);
        EXPECT_LE(std::abs(p->bias_cos_deg), 4 * sd);
        // It grows with inclination.
        EXPECT_GT(p->bias_sin_deg, previous_amplitude);
        previous_amplitude = p->bias_sin_deg;
      }
    }
  }
}

TEST(EstimatorAccuracy, StaticWithinCramerRaoBoundWhenStillAndInvalidWhileTurning) {
  for (const auto& c : reference_grid().cases) {
    const PluginCaseResult* p = c.find("static");
    ASSERT_NE(p, nullptr);
    SCOPED_TRACE(testing::Message() << "I " << c.inclination_deg << " rpm " << c.rpm << " SNRa " << c.snr_accel_db);
    if (c.rpm == 0) {
      EXPECT_EQ(p->valid, p->records);
      EXPECT_LE(p->rms_azimuth_error_deg, 1.25 * c.crb_azimuth_deg);
      EXPECT_LE(p->rms_inclination_error_deg, 1.25 * c.crb_inclination_deg);
    } else {
      EXPECT_EQ(p->valid, 0);
      EXPECT_NE(p->first_invalid_reason.find("platform rotating"), std::string::npos) << p->first_invalid_reason;
    }
  }
}

// Beyond the paper: constant radial biases do not turn with the platform, so the rotating
// estimators remove them; the static formula cannot.
TEST(EstimatorAccuracy, RadialSensorBiasesBarelyAffectRotatingEstimators) {
  CompareConfig clean = CompareConfig::reference_grid();
  clean.seeds = kSeeds;
  clean.rpms = {60, 120};
  clean.plugins = {"integral", "compensated"};
  CompareConfig biased = clean;
  biased.base.accel_errors.bias = Eigen::Vector3d(0.004, 0.004, 0);
  biased.base.mag_errors.bias = Eigen::Vector3d(0.07, 0.07, 0);
  const CompareResult a = run_compare(clean), b = run_compare(biased);
  std::cout << "with radial biases (accel 0.004 m/s^2, mag 0.07 uT on x and y):\n";
  write_report(std::cout, b);
  ASSERT_EQ(a.cases.size(), b.cases.size());
  for (std::size_t i = 0; i < a.cases.size(); ++i) {
    for (const char* plugin : {"integral", "compensated"}) {
      const PluginCaseResult* pa = a.cases[i].find(plugin);
      const PluginCaseResult* pb = b.cases[i].find(plugin);
      SCOPED_TRACE(testing::Message() << plugin << " I " << a.cases[i].inclination_deg << " rpm " << a.cases[i].rpm
                                      << " SNRa " << a.cases[i].snr_accel_db);
      EXPECT_LE(pb->rms_azimuth_error_deg, 1.5 * pa->rms_azimuth_error_deg);
    }
  }
  // The static formula at 0 rpm with the same biases, for the record (not a claim).
  CompareConfig still = biased;
  still.rpms = {0};
  still.plugins = {"static", "compensated"};
  std::cout << "static platform (0 rpm) with the same biases:\n";
  write_report(std::cout, run_compare(still));
}

}  // namespace
}  // namespace plumb::compare
