// Noiseless samples carry the exact geometry of docs/conventions.md: the closed-form attitude gives
// back the true angles, gravity and field keep their magnitudes and dip, and the gyros see the
// platform rate with the sign that makes dC/dt = -[w x] C.
#include <cmath>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/platform.hpp"
#include "cross_matrix.hpp"

namespace plumb::sim {
namespace {

Scenario noiseless(double inc, double azi, double tf0, double rpm) {
  Scenario s;
  s.g = 9.81;
  s.inclination_deg = inc;
  s.azimuth_deg = azi;
  s.toolface0_deg = tf0;
  s.rotation.rpm = rpm;
  s.duration_s = 1.0;
  s.sample_rate_hz = 50;
  return s;
}

// Round-off only: components are computed to ~1e-16 relative, and the toolface and azimuth
// conditioning is 1/sinI (about 115 at 0.5 deg), so 1e-9 deg is far above the expected error.
constexpr double kAngleTolDeg = 1e-9;

TEST(PlatformGeometry, ClosedFormGivesBackTruthOverTheGrid) {
  for (double inc : {0.5, 1.0, 2.0, 5.0, 10.0, 30.0, 60.0, 89.0, 90.0, 91.0, 120.0, 150.0, 170.0})
    for (double azi = 0; azi < 360; azi += 30)
      for (double tf0 : {0.0, 45.0, 200.0}) {
        PlatformSimulator sim(noiseless(inc, azi, tf0, 37.0));
        while (!sim.done()) {
          TruthSample truth;
          const Sample s = sim.next(&truth);
          const ClosedForm cf = closed_form_attitude(-s.f, s.b);
          ASSERT_TRUE(cf.valid && cf.azimuth_valid && cf.toolface_valid);
          ASSERT_NEAR(cf.inclination_deg, inc, kAngleTolDeg);
          ASSERT_NEAR(wrap_deg_180(cf.azimuth_deg - azi), 0.0, kAngleTolDeg) << "I=" << inc << " A=" << azi;
          ASSERT_NEAR(wrap_deg_180(cf.gravity_toolface_deg - truth.toolface_deg), 0.0, kAngleTolDeg);
          // Constant speed: T = T0 + 6 deg/s per rpm.
          ASSERT_NEAR(wrap_deg_180(truth.toolface_deg - (tf0 + 37.0 * 6.0 * s.t)), 0.0, 1e-9);
          ASSERT_EQ(truth.inclination_deg, inc);
          ASSERT_EQ(truth.azimuth_deg, azi);
          ASSERT_EQ(truth.rpm, 37.0);
        }
      }
}

TEST(PlatformGeometry, MagnitudesAndDipArePreservedWhileTurning) {
  for (double inc : {0.5, 45.0, 135.0})
    for (double azi : {0.0, 100.0, 250.0}) {
      Scenario sc = noiseless(inc, azi, 10.0, 120.0);
      sc.rotation = parse_profile("stickslip:90:0.7");
      PlatformSimulator sim(sc);
      for (const Sample& s : sim.run()) {
        // The sensors sit on the axis: turning adds no centripetal force, so |f| = g exactly.
        ASSERT_NEAR(s.f.norm(), sc.g, 1e-12 * sc.g);
        ASSERT_NEAR(s.b.norm(), sc.total_b, 1e-12 * sc.total_b);
        const double dip = std::asin((-s.f).dot(s.b) / (s.f.norm() * s.b.norm())) / kDeg;
        ASSERT_NEAR(dip, sc.dip_deg, 1e-9);
      }
    }
}

TEST(PlatformGeometry, VerticalHoleMagneticToolfaceIsAzimuthPlusToolface) {
  Scenario sc = noiseless(0.0, 70.0, 15.0, 60.0);
  PlatformSimulator sim(sc);
  while (!sim.done()) {
    TruthSample truth;
    const Sample s = sim.next(&truth);
    const double m = std::atan2(-s.b.y(), s.b.x()) / kDeg;
    ASSERT_NEAR(wrap_deg_180(m - (70.0 + truth.toolface_deg)), 0.0, 1e-9);
  }
}

TEST(PlatformGeometry, GyroSignMatchesFiniteDifferenceOfAttitude) {
  for (double rpm : {60.0, -45.0}) {
    Scenario sc = noiseless(30.0, 40.0, 0.0, rpm);
    sc.earth_rate = 0;  // platform part only
    sc.sample_rate_hz = 1000;
    PlatformSimulator sim(sc);
    std::vector<TruthSample> truth;
    const auto samples = sim.run(&truth);
    const double inc = sc.inclination_deg * kDeg, azi = sc.azimuth_deg * kDeg;
    const double dt = 1.0 / sc.sample_rate_hz;
    const double w = std::abs(rpm) * 2 * kPi / 60;
    for (std::size_t k = 1; k + 1 < samples.size(); k += 97) {
      const Eigen::Matrix3d c_prev = c_nb(inc, azi, truth[k - 1].toolface_deg * kDeg);
      const Eigen::Matrix3d c_next = c_nb(inc, azi, truth[k + 1].toolface_deg * kDeg);
      const Eigen::Matrix3d c = c_nb(inc, azi, truth[k].toolface_deg * kDeg);
      const Eigen::Matrix3d dc = (c_next - c_prev) / (2 * dt);
      // Central difference error ~ w^3 dt^2 / 6; a wrong sign would be off by 2w.
      const double tol = 10 * w * w * w * dt * dt;
      EXPECT_LT((dc + test::cross_matrix(samples[k].w) * c).norm(), tol) << "rpm " << rpm << " k " << k;
      EXPECT_NEAR(samples[k].w.z(), rpm * 2 * kPi / 60, 1e-12);
    }
  }
}

TEST(PlatformGeometry, GyrosSeeEarthRateWhenStill) {
  Scenario sc = noiseless(25.0, 130.0, 70.0, 0.0);
  sc.latitude_deg = 52;
  PlatformSimulator sim(sc);
  const double lat = sc.latitude_deg * kDeg;
  for (const Sample& s : sim.run()) {
    ASSERT_NEAR(s.w.norm(), sc.earth_rate, 1e-15);
    // Projection on the down direction (gravity) is -Omega sinLat in NED; on magnetic north (the
    // horizontal part of the field) it is Omega cosLat.
    const Eigen::Vector3d down = -s.f / s.f.norm();
    ASSERT_NEAR(s.w.dot(down), -sc.earth_rate * std::sin(lat), 1e-15);
    const Eigen::Vector3d north = (s.b - s.b.dot(down) * down).normalized();
    ASSERT_NEAR(s.w.dot(north), sc.earth_rate * std::cos(lat), 1e-15);
  }
}

TEST(PlatformGeometry, SampleBookkeeping) {
  Scenario sc = noiseless(3.0, 0.0, 0.0, 60.0);
  sc.duration_s = 2.0;
  sc.sample_rate_hz = 100;
  PlatformSimulator sim(sc);
  EXPECT_EQ(sim.sample_count(), 200u);
  const auto samples = sim.run();
  ASSERT_EQ(samples.size(), 200u);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    EXPECT_EQ(samples[k].seq, k);
    EXPECT_DOUBLE_EQ(samples[k].t, static_cast<double>(k) / 100.0);
    EXPECT_EQ(samples[k].flags, flags::kHasGyro | flags::kHasTemperature);
  }
  EXPECT_TRUE(sim.done());
  sc.with_gyro = false;
  PlatformSimulator no_gyro(sc);
  const Sample s = no_gyro.next();
  EXPECT_EQ(s.flags, flags::kHasTemperature);
  EXPECT_EQ(s.w, Eigen::Vector3d::Zero());
}

TEST(PlatformGeometry, KeepsGoingPastTheDurationWithoutAJump) {
  Scenario sc = noiseless(3.0, 0.0, 0.0, 60.0);
  sc.duration_s = 0.5;
  PlatformSimulator sim(sc);
  TruthSample prev, cur;
  sim.next(&prev);
  for (int k = 1; k < 100; ++k) {
    sim.next(&cur);
    EXPECT_NEAR(wrap_deg_180(cur.toolface_deg - prev.toolface_deg), 360.0 / sc.sample_rate_hz, 1e-9);
    prev = cur;
  }
  EXPECT_EQ(sim.index(), 100u);
}

TEST(PlatformGeometry, RejectsImpossibleScenarios) {
  Scenario sc;
  sc.sample_rate_hz = 0;
  EXPECT_THROW(PlatformSimulator{sc}, std::invalid_argument);
  sc = Scenario{};
  sc.inclination_deg = 181;
  EXPECT_THROW(PlatformSimulator{sc}, std::invalid_argument);
  sc = Scenario{};
  sc.noise.sigma_accel = -1;
  EXPECT_THROW(PlatformSimulator{sc}, std::invalid_argument);
}

}  // namespace
}  // namespace plumb::sim
