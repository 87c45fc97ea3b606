// The bound against its small-inclination closed form and its scaling laws.
#include <gtest/gtest.h>

#include <cmath>

#include "plumb/core/attitude.hpp"
#include "plumb/windowed/cramer_rao.hpp"

namespace plumb::windowed {
namespace {

CrbCase reference(double inc, double az, double rpm, double snr_a_db) {
  CrbCase c;
  c.g = 10, c.total_b = 48.4, c.dip_deg = 45.5;
  c.inclination_deg = inc, c.azimuth_deg = az, c.rpm = rpm;
  c.sigma_accel = sigma_from_snr(c.g * std::sin(inc * kDeg), snr_a_db);
  const Eigen::Vector3d b = field_tool(inc * kDeg, az * kDeg, 0, c.total_b, c.dip_deg * kDeg);
  c.sigma_mag = sigma_from_snr(std::hypot(b.x(), b.y()), 20);
  return c;
}

// Azimuth is the phase difference alpha of the gravity and field sinusoids, each phase known to
// sigma/(amplitude sqrt N) = 1/sqrt(2 SNR N); inclination is the gravity amplitude over g, known to
// sigma_a/sqrt(N) per radial direction. The axial channels add little at small inclination.
TEST(CramerRao, MatchesSmallInclinationClosedForm) {
  for (double rpm : {60.0, 120.0}) {
    for (double snr : {10.0, 20.0}) {
      const CrbCase c = reference(0.5, 40, rpm, snr);
      const CrbResult r = cramer_rao_bound(c);
      ASSERT_TRUE(r.ok);
      const double n = 1000;
      const double snr_a = std::pow(10.0, snr / 10), snr_m = 100;
      const double az = std::sqrt((1 / (2 * snr_a) + 1 / (2 * snr_m)) / n) / kDeg;
      const double inc = c.sigma_accel / (c.g * std::sqrt(n)) / kDeg;
      EXPECT_NEAR(r.azimuth_deg, az, 0.03 * az);
      EXPECT_NEAR(r.inclination_deg, inc, 0.03 * inc);
    }
  }
}

TEST(CramerRao, ScalesWithNoiseAndSampleCount) {
  const CrbCase c = reference(1, 100, 60, 10);
  const CrbResult base = cramer_rao_bound(c);
  CrbCase noisier = c;
  noisier.sigma_accel *= 2, noisier.sigma_mag *= 2;
  const CrbResult twice = cramer_rao_bound(noisier);
  EXPECT_NEAR(twice.azimuth_deg, 2 * base.azimuth_deg, 1e-6 * base.azimuth_deg);
  EXPECT_NEAR(twice.inclination_deg, 2 * base.inclination_deg, 1e-6 * base.inclination_deg);
  // Four times the samples over the same whole revolutions halves the bounds.
  CrbCase denser = c;
  denser.sample_rate_hz *= 4;
  const CrbResult dense = cramer_rao_bound(denser);
  EXPECT_NEAR(dense.azimuth_deg, 0.5 * base.azimuth_deg, 0.01 * base.azimuth_deg);
  EXPECT_NEAR(dense.inclination_deg, 0.5 * base.inclination_deg, 0.01 * base.inclination_deg);
}

TEST(CramerRao, RefusesDegenerateInput) {
  CrbCase c = reference(1, 0, 60, 10);
  c.sigma_accel = 0;
  EXPECT_FALSE(cramer_rao_bound(c).ok);
  c = reference(1, 0, 60, 10);
  c.duration_s = 0;
  EXPECT_FALSE(cramer_rao_bound(c).ok);
}

TEST(CramerRao, SigmaFromSnrFollowsConventions) {
  // SNR = 10 log10(a^2 / 2 / sigma^2)
  const double s = sigma_from_snr(2.0, 20);
  EXPECT_NEAR(10 * std::log10(4.0 / 2 / (s * s)), 20, 1e-12);
}

}  // namespace
}  // namespace plumb::windowed
