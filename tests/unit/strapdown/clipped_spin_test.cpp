// The spin of a tool whose axial gyro reads at its range, followed from what the other sensors see
// turn across the axis (ClippedSpin): against a tool turned through a known stick-slip, the turn it
// gives over a slip is the truth's within its own stated sigma, whether it follows the field or,
// under vibration, gravity; its rate stays beyond the range; near vertical without a field it
// declines; across a gap, the field on either side measures the turn the gap hid.
#include <cmath>
#include <numbers>
#include <optional>
#include <random>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "plumb/strapdown/clipped_spin.hpp"

namespace plumb::strapdown {
namespace {

constexpr double kDegSpin = std::numbers::pi / 180.0;
constexpr double kGravitySpin = 9.81;

struct SpinRun {
  double true_turn = 0, followed_turn = 0, variance = 0;
  double slowest_rate = 1e9;
  int declined = 0;
};

// A tool at inclination `inc_deg` (azimuth 30) turning at 400 +- 250 deg/s about its axis (a slip
// past a 300 deg/s gyro) for `seconds` at 100 Hz: every reading's gyro clipped at the range, the
// field (dip 60) or not, white noise of `across_noise` m/s^2 on the accelerometers across the axis.
SpinRun follow_slip(double inc_deg, bool field, double across_noise, double seconds = 2.0) {
  NavigatorConfig config;
  config.gyro_range = 300 * kDegSpin;
  config.gyro_rate_max = 3000 * kDegSpin;
  ClippedSpin spin;
  spin.reset(config);
  const double dt = 0.01;
  const Eigen::Matrix3d tilt = (Eigen::AngleAxisd(30 * kDegSpin, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(inc_deg * kDegSpin, Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  const Eigen::Vector3d up(0, 0, -kGravitySpin);
  const Eigen::Vector3d b_nav(25 * std::cos(60 * kDegSpin), 0, 25 * std::sin(60 * kDegSpin));
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, across_noise);
  const auto rate_at = [](double t) { return (400 + 250 * std::sin(2 * std::numbers::pi * t / 2.0)) * kDegSpin; };
  const auto reading_at = [&](double t, double toolface) {
    const Eigen::Matrix3d c_bn = tilt * Eigen::AngleAxisd(toolface, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    InputReading r;
    r.t = t;
    r.f = c_bn.transpose() * up + Eigen::Vector3d(noise(rng), noise(rng), 0);
    r.w = Eigen::Vector3d(0, 0, rate_at(t));
    if (field) r.b = c_bn.transpose() * b_nav;
    return std::pair{r, c_bn};
  };
  SpinRun run;
  double toolface = 0;
  auto [prev, c_prev] = reading_at(0, 0);
  prev.w.z() = config.gyro_range;  // the last reading the gyro read
  for (int k = 1; k <= static_cast<int>(seconds / dt); ++k) {
    const double t = k * dt;
    const double turn = 0.5 * (rate_at(t - dt) + rate_at(t)) * dt;  // the truth's, by the trapezoid
    toolface += turn;
    run.true_turn += turn;
    auto [in, c_bn] = reading_at(t, toolface);
    in.w.z() = config.gyro_range;  // clipped
    in.clipped = kAxialGyroClipped;
    const std::optional<ClippedSpin::Spin> s = spin.through(in, prev, dt, c_prev, kGravitySpin);
    if (!s) {
      ++run.declined;
      in.w.z() = config.gyro_range;
    } else {
      run.followed_turn += 0.5 * (prev.w.z() + s->rate) * dt + s->turn;
      run.slowest_rate = std::min(run.slowest_rate, s->rate);
      in.w.z() = s->rate;
    }
    run.variance += spin.take_variance();
    prev = in;
    c_prev = c_bn;
  }
  return run;
}

TEST(ClippedSpin, FollowsTheFieldThroughASlip) {
  const SpinRun run = follow_slip(60, true, 1.0);
  EXPECT_EQ(run.declined, 0);
  // 800 degrees turned in 2 s; the gyro alone would say 600.
  EXPECT_NEAR(run.true_turn / kDegSpin, 800, 1);
  // The loop lags the slip's change of rate a little (under a degree at 14 rad/s^2), within its sigma.
  EXPECT_NEAR(run.followed_turn, run.true_turn, 1 * kDegSpin);
  EXPECT_LT(std::abs(run.followed_turn - run.true_turn), 3 * std::sqrt(run.variance));
  EXPECT_GE(run.slowest_rate, 300 * kDegSpin);
}

TEST(ClippedSpin, FollowsGravityUnderVibrationWithinItsSigma) {
  const SpinRun run = follow_slip(60, false, 1.0);
  EXPECT_EQ(run.declined, 0);
  const double sigma = std::sqrt(run.variance);
  EXPECT_GT(sigma, 0.2 * kDegSpin);  // the vibration costs something
  EXPECT_LT(std::abs(run.followed_turn - run.true_turn), 3 * sigma);
  EXPECT_LT(std::abs(run.followed_turn - run.true_turn), 5 * kDegSpin);
  EXPECT_GE(run.slowest_rate, 300 * kDegSpin);
}

TEST(ClippedSpin, DeclinesNearVerticalWithoutAField) {
  EXPECT_GT(follow_slip(5, false, 0.1, 0.5).declined, 0);
  // With the field across the axis it still follows.
  EXPECT_EQ(follow_slip(5, true, 0.1, 0.5).declined, 0);
}

// Across a gap the tool turned 100 deg about its axis where the made-up readings turned it 70: the
// field across the axis on either side says the 30 left, whatever whole turns the gap held.
TEST(ClippedSpin, TheFieldAcrossTheAxisMeasuresAGapsTurn) {
  const Eigen::Matrix3d tilt = (Eigen::AngleAxisd(40 * kDegSpin, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(70 * kDegSpin, Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  const Eigen::Vector3d b_nav(20, 3, 40);
  const auto about_axis = [&](double deg) -> Eigen::Matrix3d {
    return tilt * Eigen::AngleAxisd(deg * kDegSpin, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  };
  for (const double whole_turns : {0.0, 2.0}) {
    InputReading before, after;
    before.b = about_axis(15).transpose() * b_nav;
    after.b = about_axis(15 + 100 + 360 * whole_turns).transpose() * b_nav;
    const std::optional<double> left = unseen_turn_across_gap(before, after, about_axis(15), about_axis(15 + 70));
    ASSERT_TRUE(left);
    EXPECT_NEAR(*left / kDegSpin, 30, 1e-9);
  }
  // The field along the axis shows no turn about it.
  InputReading along;
  along.b = about_axis(0).transpose() * (tilt.col(2) * 45.0);
  EXPECT_FALSE(unseen_turn_across_gap(along, along, about_axis(0), about_axis(0)));
}

}  // namespace
}  // namespace plumb::strapdown
