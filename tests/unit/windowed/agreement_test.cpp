// plumb compare on a recording: the per-plugin summary and the agreement between two plugins,
// checked on rows whose truth and noise are known.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/compare/agreement.hpp"

namespace plumb::compare {
namespace {

Estimate row(double t, double inclination, double azimuth, double sigma) {
  Estimate e;
  e.t_end = t;
  e.inclination_deg = inclination;
  e.azimuth_deg = azimuth;
  e.inclination_sd_deg = e.azimuth_sd_deg = sigma;
  e.valid = e.azimuth_valid = true;
  return e;
}

// Two honest plugins (unbiased, sigma as reported) of one tool: their differences have sigma
// s sqrt(2), so 95.4 % of them fall within 2 sqrt(s1^2 + s2^2); one biased by 7 sigmas of the
// difference (1 deg against s = 0.1 deg) hardly ever does.
TEST(Agreement, HonestPluginsAgreeWithinTwoCombinedSigmaAboutNinetyFivePercent) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.1);
  std::vector<Estimate> a, b, biased;
  for (int k = 0; k < 4000; ++k) {
    const double t = 0.5 * k, inclination = 30.0 + 0.001 * k, azimuth = std::fmod(350.0 + 0.01 * k, 360.0);
    a.push_back(row(t, inclination + noise(rng), azimuth + noise(rng), 0.1));
    b.push_back(row(t + 0.01, inclination + noise(rng), azimuth + noise(rng), 0.1));
    biased.push_back(row(t, inclination + 1.0 + noise(rng), azimuth + noise(rng), 0.1));
  }
  const Agreement honest = agree(a, b, 0.1);
  EXPECT_EQ(honest.matched, 4000u);
  EXPECT_NEAR(honest.rms_inclination_diff_deg, 0.1 * std::sqrt(2.0), 0.006);
  EXPECT_NEAR(honest.rms_azimuth_diff_deg, 0.1 * std::sqrt(2.0), 0.006);  // across 360 -> 0 too
  EXPECT_NEAR(honest.inclination_within_2sigma, 0.954, 0.012);
  EXPECT_NEAR(honest.azimuth_within_2sigma, 0.954, 0.012);
  const Agreement off = agree(a, biased, 0.1);
  EXPECT_LT(off.inclination_within_2sigma, 0.001);
  EXPECT_NEAR(off.azimuth_within_2sigma, 0.954, 0.012);
}

TEST(Agreement, RowsFarApartInTimeAreNotCompared) {
  const std::vector<Estimate> a{row(0, 10, 10, 0.1), row(1, 10, 10, 0.1)};
  const std::vector<Estimate> b{row(0.3, 11, 10, 0.1), row(1.3, 11, 10, 0.1)};
  EXPECT_EQ(agree(a, b, 0.2).matched, 0u);
  EXPECT_EQ(agree(a, b, 0.5).matched, 2u);
  EXPECT_DOUBLE_EQ(agree(a, b, 0.5).rms_inclination_diff_deg, 1.0);
  Estimate no_sigma = row(0, 10, 10, 0);
  EXPECT_LT(agree(a, {no_sigma}, 0.5).inclination_within_2sigma, 0.0);  // nothing to judge by
}

// Azimuths on both sides of north average to north, with their spread, not to south.
TEST(Agreement, SummaryAveragesAzimuthOnTheCircle) {
  std::vector<Estimate> rows;
  for (int k = 0; k < 100; ++k) rows.push_back(row(k, 5.0 + (k % 2 ? 0.2 : -0.2), k % 2 ? 359.0 : 1.0, 0.3));
  rows.push_back(Estimate{});  // an invalid row is counted, not averaged
  const PluginSummary s = summarize("x", rows);
  EXPECT_EQ(s.rows, 101u);
  EXPECT_EQ(s.valid, 100u);
  EXPECT_NEAR(std::fmod(s.azimuth_mean_deg + 180.0, 360.0) - 180.0, 0.0, 1e-9);
  EXPECT_NEAR(s.azimuth_sd_deg, 1.0, 1e-3);
  EXPECT_NEAR(s.inclination_mean_deg, 5.0, 1e-12);
  EXPECT_NEAR(s.inclination_sd_deg, 0.2, 1e-9);
  EXPECT_DOUBLE_EQ(s.median_azimuth_sigma_deg, 0.3);
}

}  // namespace
}  // namespace plumb::compare
