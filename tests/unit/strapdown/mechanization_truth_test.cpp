// The navigator's own two-rate mechanization against the drilling simulator's truth: an error-free
// IMU, started from the true state, with the full update at the filter's epochs (every 5th reading
// at 100 Hz, the default 20 Hz) and no measurement, must return the true attitude, velocity and
// position at least as closely as the independent reference integrator of tests/unit/sim does
// (DrillingStrapdown.ErrorFreeImuReturnsTheTruthOnTheReferenceRun: 4e-5 deg, 0.6 m, 2.5e-3 m/s), and
// the rate of the full update must not matter. Measured: attitude 1.7e-6 deg at most, end position
// 0.015 m, velocity 4e-5 m/s; the Magnus step is exact for the toolface spin about the fixed tool
// axis, where RK4 loses th^5/1920 per step (the reference's 2.9e-5 deg and, through gravity,
// 0.46 m; the single-rate RK4 mechanization this replaced left 3.0e-5 deg and 0.46 m). The bounds
// below are about twice the measured values.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/drilling.hpp"
#include "plumb/sim/walk.hpp"
#include "plumb/strapdown/earth.hpp"
#include "plumb/strapdown/mechanization.hpp"

namespace plumb::strapdown::test {
namespace {

struct Residual {
  double max_attitude_deg = 0, position_m = 0, velocity_mps = 0;
  NavState end;
};

double angle_between_deg(const Eigen::Matrix3d& c_bn, const Eigen::Matrix3d& c_nb_true) {
  return Eigen::AngleAxisd(c_bn * c_nb_true).angle() / kDeg;
}

sim::DrillingScenario error_free(double rate_hz) {
  sim::DrillingScenario s = sim::DrillingScenario::reference(sim::ImuGrade::perfect(), rate_hz);
  s.magnetometer.sigma_uT = 0;
  s.vibration = sim::Vibration{};
  return s;
}

// Full updates every `epoch` readings (1: every reading). `at(t)` gives the true c_nb; the end
// is compared with the last truth sample.
template <typename Simulator, typename TruthAt>
Residual integrate(Simulator& sim, double latitude_deg, double g, TruthAt at, int epoch) {
  std::vector<TruthSample> truth;
  const std::vector<Sample> s = sim.run(&truth);
  Mechanization mech(earth_rate_ned(latitude_deg * kDeg), g);
  const auto start = at(s.front().t);
  NavState x;
  x.q = Eigen::Quaterniond(Eigen::Matrix3d(start.c_nb.transpose()));
  x.v = start.velocity;
  x.p = start.position;
  mech.begin(x);
  Residual r;
  auto reading = [&](std::size_t k) { return ImuReading{s[k].t, s[k].f, s[k].w}; };
  for (std::size_t k = 1; k < s.size(); ++k) {
    const ImuReading before = k >= 2 ? reading(k - 2) : ImuReading{};
    mech.step(reading(k - 1), reading(k), k >= 2 ? &before : nullptr);
    if (k % epoch == 0 || k + 1 == s.size()) {
      mech.finish(x);
      mech.begin(x);
    }
    if (k % 20 == 0) {
      const double err = angle_between_deg(mech.state().q.toRotationMatrix(), at(s[k].t).c_nb);
      r.max_attitude_deg = std::max(r.max_attitude_deg, err);
    }
  }
  const TruthSample& end = truth.back();
  r.position_m = (x.p - Eigen::Vector3d(end.north_m, end.east_m, end.down_m)).norm();
  r.velocity_mps = (x.v - Eigen::Vector3d(end.vn_mps, end.ve_mps, end.vd_mps)).norm();
  r.end = x;
  return r;
}

Residual integrate(const sim::DrillingScenario& scenario, int epoch) {
  sim::DrillingSimulator sim(scenario);
  return integrate(sim, scenario.latitude_deg, scenario.g, [&](double t) { return sim.trajectory().at(t); }, epoch);
}

Residual integrate(const sim::WalkScenario& scenario, int epoch) {
  sim::WalkSimulator sim(scenario);
  return integrate(sim, scenario.latitude_deg, scenario.g, [&](double t) { return sim.path().at(t); }, epoch);
}

sim::WalkScenario error_free(sim::WalkScenario s) {
  s.grade = sim::ImuGrade::perfect();
  s.mag_sigma_uT = 0;
  return s;
}

TEST(MechanizationTruth, ErrorFreeImuReturnsTheTruthOnTheReferenceRun) {
  const Residual r = integrate(error_free(100), 5);
  std::printf("reference run, 100 Hz, full update at 20 Hz: attitude %.2e deg, position %.3e m, velocity %.2e m/s\n",
              r.max_attitude_deg, r.position_m, r.velocity_mps);
  EXPECT_LT(r.max_attitude_deg, 4e-6);
  EXPECT_LT(r.position_m, 0.03);
  EXPECT_LT(r.velocity_mps, 1e-4);
}

// The full update's rate is bookkeeping, not integration: every 5th reading and every reading end
// at the same state to far below any sensor's resolution (what differs is the Coriolis and earth
// terms' order within an epoch).
TEST(MechanizationTruth, TheFullUpdateRateDoesNotMatter) {
  const Residual every = integrate(error_free(100), 1), fifth = integrate(error_free(100), 5);
  const double attitude = Eigen::AngleAxisd(every.end.q * fifth.end.q.inverse()).angle();
  std::printf("full update every reading vs every 5th: attitude %.2e rad, position %.2e m, velocity %.2e m/s\n",
              attitude, (every.end.p - fifth.end.p).norm(), (every.end.v - fifth.end.v).norm());
  EXPECT_LT(attitude, 1e-10);
  EXPECT_LT((every.end.p - fifth.end.p).norm(), 1e-3);
  EXPECT_LT((every.end.v - fifth.end.v).norm(), 1e-6);
  EXPECT_LT(std::abs(every.end.s - fifth.end.s), 1e-3);
}

// A foot swings its pitch at up to 6.3 rad/s while it turns and rolls (0.016 rad per step at
// 400 Hz, about no fixed axis), so the coning term matters. Measured on the 60 m loop, full update
// at 20 Hz: attitude 4.9e-5 deg at most and end position 2.3e-3 m at 400 Hz, 6.2e-6 deg and 3.0e-4 m
// at 800 Hz; the single-rate RK4 mechanization this replaced left the same to two digits (4.85e-5,
// 6.19e-6 deg). What remains vanishes with the step by 2^3 per halving: the rates are interpolated
// by the parabola through the last three readings, one-sided because the state advances as each
// reading arrives (tests/unit/sim's reference integrator, with a centred cubic that waits for the
// next reading, is 4th order). Bounds: twice the measured values, and the order.
TEST(MechanizationTruth, WalkResidualShrinksAsTheStepShrinks) {
  const Residual r400 = integrate(error_free(sim::WalkScenario::loop_60m(sim::ImuGrade::perfect(), 400)), 20);
  const Residual r800 = integrate(error_free(sim::WalkScenario::loop_60m(sim::ImuGrade::perfect(), 800)), 40);
  std::printf("60 m walk, full update at 20 Hz: 400 Hz attitude %.2e deg, position %.2e m; 800 Hz %.2e deg, %.2e m\n",
              r400.max_attitude_deg, r400.position_m, r800.max_attitude_deg, r800.position_m);
  EXPECT_LT(r400.max_attitude_deg, 1e-4);
  EXPECT_LT(r400.position_m, 5e-3);
  EXPECT_LT(r800.max_attitude_deg, 1.25e-5);
  EXPECT_LT(r800.position_m, 6e-4);
  EXPECT_GT(r400.max_attitude_deg / r800.max_attitude_deg, 6.0);
  EXPECT_GT(r400.position_m / r800.position_m, 6.0);
}

}  // namespace
}  // namespace plumb::strapdown::test
