// A plugin whose assumptions the data violate says so
// (invalid, the reason, standard deviation 0 = unknown) instead of printing a precise-looking number;
// near vertical the azimuth's sigma grows like 1/sinI and its validity clears at the stated limit.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "estimator_test_support.hpp"
#include "plumb/core/attitude.hpp"
#include "plumb/estimator/estimator.hpp"

namespace plumb::test {
namespace {

sim::Scenario scenario(double inc, double az, double rpm) {
  sim::Scenario s = sim::Scenario::reference(inc, az, rpm, 20);
  s.g = 9.80665;
  // Fixed noise (not an SNR, which would shrink the noise with sinI).
  s.noise.snr_accel_db.reset(), s.noise.snr_mag_db.reset();
  s.noise.sigma_accel = 0.01, s.noise.sigma_mag = 0.1;
  return s;
}

// Every sample's specific force times k: a stream k g strong (a units or scale mistake).
std::vector<Sample> scaled_gravity(std::vector<Sample> samples, double k) {
  for (auto& x : samples) x.f *= k;
  return samples;
}

TEST(EstimatorAssumptions, GravityFarFromTheEarthsIsRefusedWithTheReason) {
  const auto samples = scaled_gravity(simulate(scenario(30, 100, 0)), 4.0);
  for (const char* plugin : kAllPlugins) {
    SCOPED_TRACE(plugin);
    const auto est = run_plugin(plugin, samples);
    ASSERT_EQ(est.size(), 1u);
    EXPECT_FALSE(est[0].valid);
    EXPECT_FALSE(est[0].azimuth_valid);
    EXPECT_NE(est[0].reason.find("|G|"), std::string::npos) << est[0].reason;
    EXPECT_EQ(est[0].inclination_sd_deg, 0);
    EXPECT_EQ(est[0].azimuth_sd_deg, 0);
    // Told that this is the local gravity, the same stream is accepted.
    const auto told = run_plugin(plugin, samples, {{"window", "0"}, {"gravity", "39.2266"}});
    EXPECT_TRUE(told[0].valid) << told[0].reason;
    EXPECT_NE(est[0].reason.find("give `gravity` if this is right"), std::string::npos) << est[0].reason;
  }
}

// A stream in g or mg, or a field in nT or gauss, is a unit mistake: the reason points at the
// input's units, not at the reference parameters.
TEST(EstimatorAssumptions, MagnitudesInAnotherUnitPointAtTheInputsUnits) {
  const auto plain = simulate(scenario(30, 100, 0));
  const std::pair<double, const char*> gravity_units[] = {{1 / 9.80665, "--units accel=g"},
                                                         {1000 / 9.80665, "--units accel=mg"}};
  for (const auto& [k, advice] : gravity_units) {
    const auto est = run_plugin("compensated", scaled_gravity(plain, k));
    ASSERT_EQ(est.size(), 1u);
    EXPECT_FALSE(est[0].valid);
    EXPECT_NE(est[0].reason.find(advice), std::string::npos) << est[0].reason;
  }
  const std::pair<double, const char*> field_units[] = {{1000, "--units mag=nT"}, {0.01, "--units mag=gauss"}};
  for (const auto& [k, advice] : field_units) {
    auto samples = plain;
    for (auto& x : samples) x.b *= k;
    const auto est = run_plugin("compensated", samples);
    ASSERT_EQ(est.size(), 1u);
    EXPECT_FALSE(est[0].azimuth_valid);
    EXPECT_NE(est[0].reason.find(advice), std::string::npos) << est[0].reason;
  }
}

TEST(EstimatorAssumptions, GivenReferencesAreCheckedWithTheirTolerances) {
  const auto samples = simulate(scenario(30, 100, 60));  // 48.4 uT, dip 45.5 deg
  for (const char* plugin : kRotatingPlugins) {
    SCOPED_TRACE(plugin);
    auto est = run_plugin(plugin, samples, {{"window", "0"}, {"gravity", "9.5"}});
    EXPECT_FALSE(est[0].valid);
    EXPECT_NE(est[0].reason.find("gravity_tol"), std::string::npos) << est[0].reason;
    est = run_plugin(plugin, samples, {{"window", "0"}, {"field_uT", "50.5"}});
    EXPECT_TRUE(est[0].valid);
    EXPECT_FALSE(est[0].azimuth_valid);
    EXPECT_EQ(est[0].azimuth_sd_deg, 0);
    EXPECT_NE(est[0].reason.find("field_tol_uT"), std::string::npos) << est[0].reason;
    est = run_plugin(plugin, samples, {{"window", "0"}, {"field_uT", "50.5"}, {"field_tol_uT", "3"}, {"dip_deg", "61"}});
    EXPECT_FALSE(est[0].azimuth_valid);
    EXPECT_NE(est[0].reason.find("dip_tol_deg"), std::string::npos) << est[0].reason;
    est = run_plugin(plugin, samples, {{"window", "0"}, {"gravity", "9.80665"}, {"field_uT", "48.4"}, {"dip_deg", "45.5"}});
    EXPECT_TRUE(est[0].valid && (est[0].azimuth_valid || std::string(plugin) == "integral")) << est[0].reason;
    EXPECT_THROW(run_plugin(plugin, samples, {{"window", "0"}, {"gravity_tolerance", "1"}}), estimator::ParameterError);
  }
}

TEST(EstimatorAssumptions, FieldChangeAfterTheFirstWindowInvalidatesTheAzimuth) {
  // 20 s in 10 s windows; the second half's field is 10 % stronger (a magnetised collar nearby).
  auto samples = simulate([] {
    auto s = scenario(30, 100, 60);
    s.duration_s = 20;
    return s;
  }());
  for (auto& x : samples) {
    if (x.t >= 10) x.b *= 1.1;
  }
  for (const char* plugin : kRotatingPlugins) {
    SCOPED_TRACE(plugin);
    const auto est = run_plugin(plugin, samples, {{"window", "10"}});
    ASSERT_EQ(est.size(), 2u);
    EXPECT_EQ(est[0].reason.find("field_tol_uT"), std::string::npos) << est[0].reason;
    EXPECT_FALSE(est[1].azimuth_valid);
    EXPECT_NE(est[1].reason.find("field_tol_uT"), std::string::npos) << est[1].reason;
  }
}

// sigma_A ~ 1/sinI near vertical (the azimuth is a phase of a radial vector of length g sinI).
TEST(EstimatorAssumptions, AzimuthSigmaGrowsTowardVerticalAndItsFlagClears) {
  for (const char* plugin : {"compensated", "static"}) {
    SCOPED_TRACE(plugin);
    double previous = 0;
    for (double inc : {2.0, 0.5, 0.1}) {
      const auto e = run_plugin(plugin, simulate(scenario(inc, 100, 0)))[0];
      ASSERT_TRUE(e.valid) << e.reason;
      EXPECT_GT(e.azimuth_sd_deg, 1.5 * previous) << inc;
      previous = e.azimuth_sd_deg;
    }
    // A limit below that sigma clears the flag and says why.
    const auto e = run_plugin(plugin, simulate(scenario(0.1, 100, 0)), {{"window", "0"}, {"max_sd_deg", "0.5"}})[0];
    EXPECT_FALSE(e.azimuth_valid);
    EXPECT_NE(e.reason.find("max_sd_deg"), std::string::npos) << e.reason;
  }
}

// The static formula's assumption (a still platform) fails while it turns: no sigma, and why.
TEST(EstimatorAssumptions, StaticReportsNoSigmaWhileTurning) {
  const auto e = run_plugin("static", simulate(scenario(30, 100, 60)))[0];
  EXPECT_FALSE(e.valid);
  EXPECT_NE(e.reason.find("platform rotating"), std::string::npos) << e.reason;
  EXPECT_EQ(e.inclination_sd_deg, 0);
  EXPECT_EQ(e.azimuth_sd_deg, 0);
  EXPECT_EQ(e.toolface_sd_deg, 0);
}

// The small-angle azimuth's error at I = 30 deg, dip 45.5 deg is tens of degrees: not valid.
TEST(EstimatorAssumptions, IntegralAzimuthInvalidBeyondItsSmallAngleRange) {
  const auto far = run_plugin("integral", simulate(scenario(30, 100, 60)))[0];
  EXPECT_TRUE(far.valid);
  EXPECT_FALSE(far.azimuth_valid);
  EXPECT_NE(far.reason.find("max_model_error_deg"), std::string::npos) << far.reason;
  const auto near = run_plugin("integral", simulate(scenario(1, 100, 60)))[0];
  EXPECT_TRUE(near.azimuth_valid) << near.reason;
}

}  // namespace
}  // namespace plumb::test
