// The drilling trajectory's kinematics against their definitions: rates against numerical
// derivatives of the attitude, velocity and acceleration against derivatives of the position, the
// position against a fine quadrature along the hole, the sensors at rest against gravity, earth rate
// and field, and exact stillness at the stops.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/drilling.hpp"

namespace plumb::sim {
namespace {

Eigen::Vector3d vee(const Eigen::Matrix3d& m) { return {m(2, 1), m(0, 2), m(1, 0)}; }

// Times inside every phase of the reference run, including the ramps and both rotary segments.
std::vector<double> probe_times(const DrillingTrajectory& tr) {
  std::vector<double> t;
  for (const auto& ph : tr.phases())
    for (double frac : {0.013, 0.02, 0.5, 0.93, 0.995}) t.push_back(ph.t0 + frac * (ph.t1 - ph.t0));
  return t;
}

TEST(DrillingPhysics, RateFormulaMatchesTheDerivativeOfTheAttitude) {
  // dC_n^b/dt = -[w_nb x] C_n^b, so w_nb = vee(-dC/dt C^T); central differences, O(h^2).
  const DrillingTrajectory tr(DrillingScenario::reference(ImuGrade::perfect()).plan);
  const double h = 1e-4;
  for (double t : probe_times(tr)) {
    const DrillingState st = tr.at(t);
    const Eigen::Matrix3d dc = (tr.at(t + h).c_nb - tr.at(t - h).c_nb) / (2 * h);
    const Eigen::Vector3d w_fd = vee(-dc * st.c_nb.transpose());
    EXPECT_LT((w_fd - st.w_nb).norm(), 1e-8 + 1e-6 * st.w_nb.norm()) << "t " << t;
  }
  // And the formula alone, for attitudes and rates far from the reference's.
  for (double inc : {0.3, 1.7, 2.9})
    for (double tf : {-2.0, 0.4, 4.0}) {
      const double di = 0.37, da = -0.81, dt_ = 1.3, azi = 0.9;
      const Eigen::Matrix3d dc = (c_nb(inc + di * h, azi + da * h, tf + dt_ * h) - c_nb(inc - di * h, azi - da * h, tf - dt_ * h)) / (2 * h);
      const Eigen::Vector3d w_fd = vee(-dc * c_nb(inc, azi, tf).transpose());
      EXPECT_LT((w_fd - rate_nb(inc, tf, di, da, dt_)).norm(), 1e-7);
    }
}

TEST(DrillingPhysics, VelocityAndAccelerationAreTheDerivativesOfThePosition) {
  const DrillingTrajectory tr(DrillingScenario::reference(ImuGrade::perfect()).plan);
  // Central differences leave h^2 x''' / 6: in the ramps about 1e-9 m/s for the velocity.
  const double h = 1e-3;
  for (double t : probe_times(tr)) {
    const DrillingState st = tr.at(t);
    const Eigen::Vector3d v_fd = (tr.at(t + h).position - tr.at(t - h).position) / (2 * h);
    const Eigen::Vector3d a_fd = (tr.at(t + h).velocity - tr.at(t - h).velocity) / (2 * h);
    EXPECT_LT((v_fd - st.velocity).norm(), 5e-9) << "t " << t;
    EXPECT_LT((a_fd - st.acceleration).norm(), 1e-8) << "t " << t;
    // Along the tool's own axis: the velocity is the third row of C_n^b times the speed.
    EXPECT_LT((st.velocity - st.speed_mps * st.c_nb.row(2).transpose()).norm(), 1e-15);
  }
}

TEST(DrillingPhysics, PositionIsTheIntegralAlongTheHole) {
  // Composite Simpson in measured depth over the attitude the trajectory reports: 1e-12 m or so.
  const DrillingTrajectory tr(DrillingScenario::reference(ImuGrade::perfect()).plan);
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  auto dir = [](const DrillingState& st) {
    return Eigen::Vector3d(std::sin(st.inclination) * std::cos(st.azimuth),
                           std::sin(st.inclination) * std::sin(st.azimuth), std::cos(st.inclination));
  };
  for (const auto& ph : tr.phases()) {
    if (!ph.moving) continue;
    EXPECT_LT((tr.at(ph.t0).position - p).norm(), 1e-9);
    // Depth is monotonic in t; Simpson in s needs the attitude at given s: I, A linear in s.
    const double length = tr.at(ph.t1).depth_m - ph.s0;
    const int n = 2000;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int i = 0; i <= n; ++i) {
      const double x = length * i / n;
      DrillingState st;
      st.inclination = ph.inc0 + ph.build * x;
      st.azimuth = ph.azi0 + ph.turn * x;
      const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
      sum += w * dir(st);
    }
    p += sum * length / n / 3.0;
  }
  const DrillingState end = tr.at(tr.duration_s());
  EXPECT_LT((end.position - p).norm(), 1e-9);
  EXPECT_NEAR(end.depth_m, 32.0, 1e-12);
  EXPECT_NEAR(tr.drilled_length_m(), 32.0, 1e-12);
}

TEST(DrillingPhysics, StopsAreExactlyStillAndSpeedIsContinuous) {
  const DrillingTrajectory tr(DrillingScenario::reference(ImuGrade::perfect()).plan);
  EXPECT_DOUBLE_EQ(tr.duration_s(), 960.0);
  EXPECT_EQ(tr.stop_count(), 4u);
  for (const auto& ph : tr.phases()) {
    if (ph.moving) {
      // At both ends of a drilling phase speed and acceleration are zero: no jump into a stop.
      for (double t : {ph.t0, ph.t1 - 1e-9}) {
        EXPECT_NEAR(tr.at(t).speed_mps, 0.0, 1e-12);
        EXPECT_NEAR(tr.at(t).acceleration.norm(), 0.0, 1e-9);
      }
      EXPECT_NEAR(tr.at(0.5 * (ph.t0 + ph.t1)).speed_mps, ph.rop, 1e-15);
      continue;
    }
    const DrillingState a = tr.at(ph.t0), b = tr.at(0.5 * (ph.t0 + ph.t1)), c = tr.at(ph.t1 - 1e-6);
    for (const DrillingState* st : {&a, &b, &c}) {
      EXPECT_TRUE(st->still);
      EXPECT_TRUE(tr.still_at(st->t));
      EXPECT_EQ(st->velocity, Eigen::Vector3d::Zero());
      EXPECT_EQ(st->acceleration, Eigen::Vector3d::Zero());
      EXPECT_EQ(st->w_nb, Eigen::Vector3d::Zero());
      EXPECT_EQ(st->c_nb, a.c_nb);
      EXPECT_EQ(st->position, a.position);
    }
  }
}

TEST(DrillingPhysics, SensorsAtRestSeeGravityEarthRateAndTheField) {
  DrillingScenario sc = DrillingScenario::reference(ImuGrade::perfect());
  sc.magnetometer.sigma_uT = 0;
  DrillingSimulator sim(sc);
  const double lat = sc.latitude_deg * kDeg;
  const Eigen::Vector3d w_ie = sc.earth_rate * Eigen::Vector3d(std::cos(lat), 0, -std::sin(lat));
  std::size_t still = 0;
  while (!sim.done()) {
    TruthSample truth;
    const Sample s = sim.next(&truth);
    const DrillingState st = sim.trajectory().at(s.t);
    EXPECT_EQ(sim.still_at(s.t), st.still);
    if (!st.still) continue;
    ++still;
    // f = -G exactly (the Coriolis term 2 w_ie x v vanishes with v), the gyros see only the earth.
    const Eigen::Vector3d G = gravity_tool(st.inclination, st.toolface, sc.g);
    ASSERT_LT((s.f + G).norm(), 1e-12);
    ASSERT_LT((s.w - st.c_nb * w_ie).norm(), 1e-18);
    ASSERT_LT((s.b - field_tool(st.inclination, st.azimuth, st.toolface, sc.total_b, sc.dip_deg * kDeg)).norm(), 1e-12);
    ASSERT_EQ(truth.vn_mps, 0.0);
    ASSERT_EQ(truth.ve_mps, 0.0);
    ASSERT_EQ(truth.vd_mps, 0.0);
    ASSERT_EQ(truth.rpm, 0.0);
  }
  EXPECT_EQ(still, 30000u);  // 60 s alignment + 4 x 60 s stops at 100 Hz
}

TEST(DrillingPhysics, ClosedFormAttitudeOfTheStillSensorsIsTheTruth) {
  // docs/conventions.md's closed form on -f and B recovers the truth's I, A, T at every still sample.
  DrillingScenario sc = DrillingScenario::reference(ImuGrade::perfect(), 10);
  sc.magnetometer.sigma_uT = 0;
  DrillingSimulator sim(sc);
  while (!sim.done()) {
    TruthSample truth;
    const Sample s = sim.next(&truth);
    if (!sim.still_at(s.t)) continue;
    const ClosedForm cf = closed_form_attitude(-s.f, s.b);
    ASSERT_TRUE(cf.valid);
    EXPECT_NEAR(cf.inclination_deg, truth.inclination_deg, 1e-9);
    EXPECT_NEAR(wrap_deg_180(cf.azimuth_deg - truth.azimuth_deg), 0.0, 1e-9);
    EXPECT_NEAR(wrap_deg_180(cf.gravity_toolface_deg - truth.toolface_deg), 0.0, 1e-9);
    EXPECT_NEAR(cf.dip_deg, sc.dip_deg, 1e-9);
  }
}

TEST(DrillingPhysics, TruthCarriesDepthPositionAndToolfaceSpeed) {
  DrillingSimulator sim(DrillingScenario::reference(ImuGrade::perfect()));
  std::vector<TruthSample> truth;
  const auto samples = sim.run(&truth);
  ASSERT_EQ(samples.size(), 96000u);
  double max_rpm = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    ASSERT_TRUE(truth[k].has_position);
    ASSERT_EQ(samples[k].flags, flags::kHasGyro | flags::kHasDepth);
    ASSERT_EQ(samples[k].depth_m, truth[k].depth_m);
    max_rpm = std::max(max_rpm, std::abs(truth[k].rpm));
    ASSERT_GE(truth[k].inclination_deg, 80.0);
    ASSERT_LE(truth[k].inclination_deg, 95.0);
  }
  EXPECT_NEAR(max_rpm, 30.0, 1e-9);
  EXPECT_NEAR(truth.back().depth_m, 32.0, 1e-12);
  // Roughly 32 m towards azimuth ~30 deg, nearly horizontal.
  EXPECT_NEAR(std::hypot(truth.back().north_m, truth.back().east_m), 32.0, 0.1);
  EXPECT_LT(std::abs(truth.back().down_m), 2.0);
}

}  // namespace
}  // namespace plumb::sim
