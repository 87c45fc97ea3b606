// Rotation profiles: the angle is the integral of the rate (checked by differencing), it is
// continuous where the profile switches phase, and the mean speeds are what the names promise.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/platform.hpp"

namespace plumb::sim {
namespace {

constexpr double kRpmToRad = 2 * kPi / 60;

// Central difference of the angle against the rate, away from rate discontinuities.
void expect_rate_is_derivative(const RotationProfile& p, double t_end) {
  const double h = 1e-5;
  for (double t = 0.0123; t < t_end; t += 0.0371) {
    const double numeric = (p.angle(t + h, 0) - p.angle(t - h, 0)) / (2 * h) / kRpmToRad;
    const double left = p.rpm_at(t - h), right = p.rpm_at(t + h);
    if (std::abs(left - right) > 1e-3 * (1 + std::abs(left))) continue;  // a step inside the difference
    // Error ~ h^2 * rate''' plus round-off ~ eps*angle/h: 1e-4 rpm covers both with margin.
    EXPECT_NEAR(numeric, p.rpm_at(t), 1e-4) << "t=" << t;
  }
}

TEST(RotationProfile, ConstantSpeed) {
  const RotationProfile p = parse_profile("60");
  EXPECT_EQ(p.kind, ProfileKind::Constant);
  EXPECT_DOUBLE_EQ(p.angle(1.0, 0.5), 0.5 + 2 * kPi);  // one revolution per second
  EXPECT_DOUBLE_EQ(p.rpm_at(3.0), 60.0);
  expect_rate_is_derivative(p, 5);
  const RotationProfile back = parse_profile("-30.5");
  EXPECT_DOUBLE_EQ(back.rpm_at(0), -30.5);
  EXPECT_LT(back.angle(1.0, 0), 0.0);  // negative rpm turns T backwards
}

TEST(RotationProfile, RampIsLinearThenConstantAndContinuous) {
  const RotationProfile p = parse_profile("ramp:0:120:5");
  EXPECT_EQ(p.kind, ProfileKind::Ramp);
  EXPECT_DOUBLE_EQ(p.rpm_at(0), 0.0);
  EXPECT_DOUBLE_EQ(p.rpm_at(2.5), 60.0);
  EXPECT_DOUBLE_EQ(p.rpm_at(7), 120.0);
  // Mean speed over the ramp is 60 rpm: 5 s make 5 revolutions.
  EXPECT_NEAR(p.angle(5, 0), 5 * 2 * kPi, 1e-12);
  const double eps = 1e-9;
  EXPECT_NEAR(p.angle(5 + eps, 0) - p.angle(5 - eps, 0), 2 * eps * 120 * kRpmToRad, 1e-9);
  expect_rate_is_derivative(p, 9);
}

TEST(RotationProfile, StopAndGoHasItsMeanAndStops) {
  const RotationProfile p = parse_profile("stopgo:60:4");
  EXPECT_EQ(p.kind, ProfileKind::StopAndGo);
  for (int n = 1; n <= 3; ++n) EXPECT_NEAR(p.angle(4.0 * n, 0), 60 * kRpmToRad * 4.0 * n, 1e-9);
  EXPECT_DOUBLE_EQ(p.rpm_at(1.0), 120.0);
  EXPECT_DOUBLE_EQ(p.rpm_at(3.0), 0.0);
  EXPECT_DOUBLE_EQ(p.angle(2.5, 0), p.angle(3.9, 0));  // still while stopped
  const double eps = 1e-9;
  for (double edge : {2.0, 4.0, 6.0})
    EXPECT_LE(std::abs(p.angle(edge + eps, 0) - p.angle(edge - eps, 0)), 2 * eps * 120 * kRpmToRad + 1e-12);
  expect_rate_is_derivative(p, 9);
}

TEST(RotationProfile, StickSlipSwingsBetweenZeroAndTwiceTheMean) {
  const RotationProfile p = parse_profile("stickslip:60:2");
  EXPECT_EQ(p.kind, ProfileKind::StickSlip);
  double lo = 1e9, hi = -1e9;
  for (double t = 0; t <= 4; t += 0.001) {
    lo = std::min(lo, p.rpm_at(t));
    hi = std::max(hi, p.rpm_at(t));
  }
  EXPECT_NEAR(lo, 0.0, 1e-9);
  EXPECT_NEAR(hi, 120.0, 1e-3);  // 1 ms grid: 120 (1 - cos(pi t/1)) within 1e-4 of the peak
  // Whole periods average to the mean speed: the angle gains exactly mean * period.
  for (int n = 1; n <= 3; ++n) EXPECT_NEAR(p.angle(2.0 * n, 0.3), 0.3 + 60 * kRpmToRad * 2.0 * n, 1e-9);
  expect_rate_is_derivative(p, 6);
}

TEST(RotationProfile, ParseErrorsSayWhatIsAccepted) {
  for (const std::string bad : {"", "abc", "ramp:1:2", "ramp:0:120:0", "stopgo:60", "stopgo:60:-1", "stickslip:x:2",
                                "spin:60:2", "60rpm", "stickslip:60:2:3", "nan"}) {
    try {
      parse_profile(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("stickslip:MEAN_RPM:PERIOD_S"), std::string::npos) << what;
      EXPECT_NE(what.find("'" + bad + "'"), std::string::npos) << what;
    }
  }
}

TEST(RotationProfile, SimulatorTruthFollowsTheProfile) {
  Scenario sc;
  sc.rotation = parse_profile("stickslip:60:2");
  sc.toolface0_deg = 10;
  sc.duration_s = 4;
  PlatformSimulator sim(sc);
  std::vector<TruthSample> truth;
  sim.run(&truth);
  for (const auto& tr : truth) {
    EXPECT_NEAR(wrap_deg_180(tr.toolface_deg - (10 + sc.rotation.angle(tr.t, 0) / kDeg)), 0.0, 1e-9);
    EXPECT_DOUBLE_EQ(tr.rpm, sc.rotation.rpm_at(tr.t));
    EXPECT_GE(tr.toolface_deg, 0.0);
    EXPECT_LT(tr.toolface_deg, 360.0);
  }
}

}  // namespace
}  // namespace plumb::sim
