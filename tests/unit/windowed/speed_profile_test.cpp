// Every rotating estimator from 0 to 300 rpm, with a non-integer number of revolutions, ramps,
// stop-and-go and stick-slip. Tolerances: the Cramer-Rao bound of the constant-speed case at the
// same inclination and SNR (speed changes move the information little when the window holds
// several turns), with room for the smoothing of an irregular platform angle; for `integral`,
// its derived small-angle error atan2(Bh sinA, cosI Bh cosA - sinI Bv) - A plus noise.
#include <gtest/gtest.h>

#include <cmath>

#include "estimator_test_support.hpp"
#include "plumb/core/attitude.hpp"
#include "plumb/windowed/cramer_rao.hpp"

namespace plumb {
namespace {

constexpr double kInclination = 2.0, kSnr = 20.0, kDip = 45.5;

double small_angle_error_deg(double az_deg) {
  const double i = kInclination * kDeg, a = az_deg * kDeg, d = kDip * kDeg;
  const double p = std::atan2(std::cos(d) * std::sin(a), std::cos(i) * std::cos(d) * std::cos(a) - std::sin(i) * std::sin(d));
  return wrap_deg_180(p / kDeg - az_deg);
}

struct Errors {
  double az_rms = 0, inc_rms = 0, crb_az = 0, crb_inc = 0;
  int valid = 0, records = 0;
};

// RMS errors over 12 azimuths x 2 seeds; for integral the derived systematic error is removed.
Errors sweep(const std::string& plugin, const std::string& profile) {
  Errors e;
  double az2 = 0, inc2 = 0;
  for (int a = 0; a < 360; a += 30) {
    for (int seed = 0; seed < 2; ++seed) {
      sim::Scenario s = sim::Scenario::reference(kInclination, a, 0, kSnr, 100 + a + seed);
      s.rotation = sim::parse_profile(profile);
      s.toolface0_deg = 37.0 * seed + a;
      const auto estimates = test::run_plugin(plugin, test::simulate(s));
      ++e.records;
      if (estimates.size() != 1 || !estimates[0].valid || !estimates[0].azimuth_valid) continue;
      ++e.valid;
      double da = wrap_deg_180(estimates[0].azimuth_deg - a);
      if (plugin == "integral") da -= small_angle_error_deg(a);
      az2 += da * da;
      const double di = estimates[0].inclination_deg - kInclination;
      inc2 += di * di;
      EXPECT_TRUE(estimates[0].all_finite());
    }
  }
  e.az_rms = std::sqrt(az2 / std::max(e.valid, 1));
  e.inc_rms = std::sqrt(inc2 / std::max(e.valid, 1));
  sim::Scenario ref = sim::Scenario::reference(kInclination, 0, 60, kSnr);
  windowed::CrbCase c;
  c.g = ref.g, c.total_b = ref.total_b, c.dip_deg = ref.dip_deg, c.inclination_deg = kInclination, c.rpm = 60;
  c.sigma_accel = ref.sigma_accel(), c.sigma_mag = ref.sigma_mag();
  const auto crb = windowed::cramer_rao_bound(c);
  e.crb_az = crb.azimuth_deg, e.crb_inc = crb.inclination_deg;
  return e;
}

class SpeedProfile : public testing::TestWithParam<const char*> {};

TEST_P(SpeedProfile, RotatingEstimatorsStayNearTheBound) {
  for (const char* plugin : test::kRotatingPlugins) {
    const Errors e = sweep(plugin, GetParam());
    SCOPED_TRACE(testing::Message() << plugin << " profile " << GetParam() << ": az rms " << e.az_rms << " crb "
                                    << e.crb_az << ", inc rms " << e.inc_rms << " crb " << e.crb_inc);
    EXPECT_EQ(e.valid, e.records);
    // 24 records: an efficient RMS has ~15 % relative spread; 1.6 x allows 4 sigma.
    const double factor = std::string(plugin) == "compensated" ? 1.6 : 2.5;
    EXPECT_LE(e.az_rms, factor * e.crb_az);
    // integral's per-sample demodulation shrinks |Z| by sigma_phi^2/2 (0.25 %): a small bias.
    EXPECT_LE(e.inc_rms, factor * e.crb_inc);
  }
}

INSTANTIATE_TEST_SUITE_P(ZeroTo300Rpm, SpeedProfile,
                         testing::Values("0", "10", "33", "150", "300", "ramp:0:120:5", "ramp:300:30:8",
                                         "stopgo:60:4", "stickslip:60:2", "stickslip:300:4"),
                         [](const testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           for (char& ch : name) {
                             if (ch == ':') ch = '_';
                           }
                           return "profile_" + name;
                         });

TEST(SpeedProfileEstimate, ReportsTheSpeed) {
  for (double rpm : {33.0, 150.0, 300.0, -60.0}) {
    sim::Scenario s = sim::Scenario::reference(1, 120, rpm, 20, 5);
    for (const char* plugin : test::kRotatingPlugins) {
      const auto estimates = test::run_plugin(plugin, test::simulate(s));
      ASSERT_EQ(estimates.size(), 1u);
      // The toolface slope over 1000 samples: its noise is far below 0.1 rpm.
      EXPECT_NEAR(estimates[0].rpm, rpm, 0.1) << plugin;
      EXPECT_TRUE(estimates[0].rotating);
    }
  }
}

// Toolface at the window end, gravity and magnetic, against the truth at the last sample.
TEST(SpeedProfileEstimate, ToolfaceAtWindowEnd) {
  sim::Scenario s = sim::Scenario::reference(2, 75, 60, 20, 9);
  s.toolface0_deg = 20;
  std::vector<TruthSample> truth;
  sim::PlatformSimulator simulator(s);
  const auto samples = simulator.run(&truth);
  for (const char* plugin : test::kAllPlugins) {
    sim::Scenario still = s;
    still.rotation = sim::parse_profile("0");
    const bool rotating_plugin = std::string(plugin) != "static";
    std::vector<TruthSample> still_truth;
    sim::PlatformSimulator still_sim(still);
    const auto still_samples = still_sim.run(&still_truth);
    const auto& data = rotating_plugin ? samples : still_samples;
    const auto& tr = rotating_plugin ? truth : still_truth;
    const auto estimates = test::run_plugin(plugin, data);
    ASSERT_EQ(estimates.size(), 1u);
    ASSERT_TRUE(estimates[0].toolface_valid) << plugin << ": " << estimates[0].reason;
    // Toolface noise: gravity phase 1/sqrt(2 SNR N) ~ 0.13 deg; 1 deg is > 5 sigma.
    EXPECT_NEAR(wrap_deg_180(estimates[0].gravity_toolface_deg - tr.back().toolface_deg), 0, 1.0) << plugin;
    const Eigen::Vector3d b = field_tool(2 * kDeg, 75 * kDeg, tr.back().toolface_deg * kDeg, s.total_b, s.dip_deg * kDeg);
    const double m = std::atan2(-b.y(), b.x()) / kDeg;
    EXPECT_NEAR(wrap_deg_180(estimates[0].magnetic_toolface_deg - m), 0, 1.0) << plugin;
  }
}

}  // namespace
}  // namespace plumb
