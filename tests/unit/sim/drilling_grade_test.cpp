// The IMU grades as statistics: a still gyro averages to its bias plus the earth rate in the tool
// frame, its scatter is ARW / sqrt(dt), the accelerometers likewise, and the drawn biases are
// N(0, grade) over seeds. Also saturation, magnetic disturbances and the depth reading.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/drilling.hpp"

namespace plumb::sim {
namespace {

DrillingScenario still_tool(const ImuGrade& grade, double seconds, double rate_hz, std::uint64_t seed) {
  DrillingScenario s;
  s.grade = grade;
  s.sample_rate_hz = rate_hz;
  s.seed = seed;
  s.plan.inclination_deg = 70;
  s.plan.azimuth_deg = 200;
  s.plan.toolface_deg = 130;
  s.plan.alignment_s = seconds;
  return s;
}

struct Stats {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), sd = Eigen::Vector3d::Zero();
};

template <typename Get>
Stats stats(const std::vector<Sample>& s, Get get) {
  Stats r;
  for (const auto& x : s) r.mean += get(x);
  r.mean /= static_cast<double>(s.size());
  for (const auto& x : s) r.sd += (get(x) - r.mean).cwiseAbs2();
  r.sd = (r.sd / static_cast<double>(s.size() - 1)).cwiseSqrt();
  return r;
}

TEST(DrillingGrade, StillGyroAveragesToBiasPlusEarthRateWithArwScatter) {
  for (const ImuGrade& grade : {ImuGrade::tactical(), ImuGrade::mems()}) {
    const DrillingScenario sc = still_tool(grade, 200, 100, 11);
    DrillingSimulator sim(sc);
    const auto s = sim.run();
    const std::size_t n = s.size();
    ASSERT_EQ(n, 20000u);
    const double dt = 0.01;
    const double lat = sc.latitude_deg * kDeg;
    const Eigen::Vector3d w_ie = sc.earth_rate * Eigen::Vector3d(std::cos(lat), 0, -std::sin(lat));
    const Eigen::Matrix3d c = c_nb(70 * kDeg, 200 * kDeg, 130 * kDeg);
    // ARW in deg/sqrt(h) -> rad/sqrt(s) is a factor kDeg / 60; per sample divide by sqrt(dt).
    const double sigma_w = grade.gyro_arw_deg_rt_h * kDeg / 60.0 / std::sqrt(dt);
    const double sigma_f = grade.accel_vrw_mps_rt_h / 60.0 / std::sqrt(dt);
    const Stats w = stats(s, [](const Sample& x) { return x.w; });
    const Stats f = stats(s, [](const Sample& x) { return x.f; });
    const double se = 1.0 / std::sqrt(static_cast<double>(n));
    for (int i = 0; i < 3; ++i) {
      // Mean within 4.5 standard errors, scatter within 4.5 standard errors of a sd (1/sqrt(2n)).
      EXPECT_NEAR(w.mean[i], sim.gyro_bias()[i] + (c * w_ie)[i], 4.5 * sigma_w * se) << grade.name << " axis " << i;
      EXPECT_NEAR(w.sd[i] / sigma_w, 1.0, 4.5 * se / std::sqrt(2.0)) << grade.name << " axis " << i;
      EXPECT_NEAR(f.mean[i], sim.accel_bias()[i] - gravity_tool(70 * kDeg, 130 * kDeg, sc.g)[i], 4.5 * sigma_f * se);
      EXPECT_NEAR(f.sd[i] / sigma_f, 1.0, 4.5 * se / std::sqrt(2.0)) << grade.name << " axis " << i;
    }
    EXPECT_NEAR(grade.gyro_noise_sigma(dt), sigma_w, 1e-18);
  }
}

TEST(DrillingGrade, DrawnBiasesFollowTheGradeOverSeeds) {
  // 3 axes x 300 seeds of N(0, sigma): RMS of bias / sigma within 1 +- 4.5 / sqrt(2 x 900).
  const ImuGrade grade = ImuGrade::tactical();
  double sum_g = 0, sum_a = 0;
  const int seeds = 300;
  for (int seed = 1; seed <= seeds; ++seed) {
    const DrillingSimulator sim(still_tool(grade, 1, 10, static_cast<std::uint64_t>(seed)));
    sum_g += (sim.gyro_bias() / grade.gyro_bias_sigma()).squaredNorm();
    sum_a += (sim.accel_bias() / grade.accel_bias_sigma()).squaredNorm();
  }
  const double tol = 4.5 / std::sqrt(2.0 * 3 * seeds);
  EXPECT_NEAR(std::sqrt(sum_g / (3 * seeds)), 1.0, tol);
  EXPECT_NEAR(std::sqrt(sum_a / (3 * seeds)), 1.0, tol);
  EXPECT_NEAR(grade.gyro_bias_sigma(), 1.0 * kDeg / 3600.0, 1e-20);
  EXPECT_NEAR(grade.accel_bias_sigma(), 0.3e-3 * 9.80665, 1e-18);
}

TEST(DrillingGrade, ExplicitBiasesAndSeedsAreHonoured) {
  DrillingScenario sc = still_tool(ImuGrade::mems(), 2, 100, 5);
  const DrillingSimulator drawn(sc);
  sc.gyro_bias = Eigen::Vector3d(1e-4, -2e-4, 3e-4);
  const DrillingSimulator given(sc);
  EXPECT_EQ(given.gyro_bias(), *sc.gyro_bias);
  EXPECT_EQ(given.accel_bias(), drawn.accel_bias());  // the other draw does not move
  // Same seed, same samples; another seed, other noise.
  const auto a = DrillingSimulator(sc).run(), b = DrillingSimulator(sc).run();
  sc.seed = 6;
  const auto c = DrillingSimulator(sc).run();
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a[k].w, b[k].w);
    ASSERT_EQ(a[k].f, b[k].f);
  }
  EXPECT_NE(a[10].w, c[10].w);
  EXPECT_EQ(ImuGrade::named("tactical").gyro_bias_deg_h, 1.0);
  EXPECT_EQ(ImuGrade::named("navigation").gyro_bias_deg_h, 0.01);
  EXPECT_EQ(ImuGrade::named("mems").gyro_arw_deg_rt_h, 0.3);
  EXPECT_THROW(ImuGrade::named("consumer"), std::invalid_argument);
  EXPECT_FALSE(std::isfinite(ImuGrade::perfect().gyro_range()));
}

TEST(DrillingGrade, GyroSaturationClipsAndFlags) {
  DrillingScenario sc = DrillingScenario::survey_stop_and_go(ImuGrade::perfect(), 100);
  sc.grade.gyro_range_deg_s = 300;  // the 60 rpm spin is 360 deg/s
  DrillingSimulator sim(sc);
  std::size_t saturated = 0;
  for (const auto& s : sim.run()) {
    EXPECT_LE(std::abs(s.w.z()), 300 * kDeg * (1 + 1e-15));
    if (s.flags & flags::kGyroSaturated) {
      ++saturated;
      EXPECT_EQ(std::abs(s.w.z()), 300 * kDeg);
    }
  }
  EXPECT_GT(saturated, 10000u);
}

TEST(DrillingGrade, DisturbedStopsShiftFieldAndDipOnlyWhileStill) {
  DrillingScenario sc = DrillingScenario::reference(ImuGrade::perfect(), 10);
  sc.magnetometer.sigma_uT = 0;
  sc.magnetometer.disturbances = {{1, 1.0, 0.5}, {3, 1.0, 0.5}};
  DrillingSimulator sim(sc);
  std::vector<TruthSample> truth;
  const auto s = sim.run(&truth);
  std::size_t disturbed = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const DrillingState st = sim.trajectory().at(s[k].t);
    const auto& phase = sim.trajectory().phases()[st.phase];
    const bool expect = phase.stop_index && (*phase.stop_index == 1 || *phase.stop_index == 3);
    const ClosedForm cf = closed_form_attitude(-s[k].f, s[k].b);
    if (expect) {
      ++disturbed;
      EXPECT_NEAR(cf.total_b, 51.0, 1e-9);
      EXPECT_NEAR(cf.dip_deg, 60.5, 1e-9);
    } else {
      EXPECT_NEAR(s[k].b.norm(), 50.0, 1e-9);
    }
  }
  EXPECT_EQ(disturbed, 2u * 600u);
  sc.magnetometer.disturbances = {{4, 1.0, 0.0}};
  EXPECT_THROW(DrillingSimulator{sc}, std::invalid_argument);
  sc.magnetometer.disturbances.clear();
  sc.magnetometer.present = false;
  for (const auto& x : DrillingSimulator(sc).run()) ASSERT_EQ(x.b, Eigen::Vector3d::Zero());
}

TEST(DrillingGrade, DepthReadingNoiseAndQuantisation) {
  DrillingScenario sc = DrillingScenario::reference(ImuGrade::perfect(), 10);
  sc.depth.sigma_m = 0.01;
  std::vector<TruthSample> truth;
  const auto noisy = DrillingSimulator(sc).run(&truth);
  double sum2 = 0;
  for (std::size_t k = 0; k < noisy.size(); ++k) sum2 += std::pow(noisy[k].depth_m - truth[k].depth_m, 2);
  // 9600 samples: the rms within 4.5 standard errors (1 / sqrt(2n) relative).
  EXPECT_NEAR(std::sqrt(sum2 / noisy.size()) / 0.01, 1.0, 4.5 / std::sqrt(2.0 * noisy.size()));
  // Rounding after the noise: every reading on the grid, within half a step of the noisy value.
  sc.depth.quantum_m = 0.05;
  const auto rounded = DrillingSimulator(sc).run();
  for (std::size_t k = 0; k < rounded.size(); ++k) {
    ASSERT_TRUE(rounded[k].flags & flags::kHasDepth);
    EXPECT_NEAR(rounded[k].depth_m / 0.05, std::round(rounded[k].depth_m / 0.05), 1e-9);
    EXPECT_LE(std::abs(rounded[k].depth_m - noisy[k].depth_m), 0.025 + 1e-12);
  }
  sc.depth.present = false;
  for (const auto& x : DrillingSimulator(sc).run()) ASSERT_FALSE(x.flags & flags::kHasDepth);
}

TEST(DrillingGrade, VibrationOnlyWhileDrilling) {
  // Tones alone give the rms; shocks are checked to arrive only while drilling.
  for (const bool shocks : {false, true}) {
    DrillingScenario sc = DrillingScenario::reference(ImuGrade::perfect(), 100);
    sc.vibration.lateral_rms = 2.0;
    if (shocks) {
      sc.vibration.lateral_rms = 0;
      sc.vibration.shock_rate_hz = 0.5;
      sc.vibration.shock_peak = 50;
    }
    DrillingSimulator sim(sc), clean(DrillingScenario::reference(ImuGrade::perfect(), 100));
    double sum2 = 0;
    std::size_t cruising = 0, shocked = 0;
    while (!sim.done()) {
      const Sample a = sim.next(), b = clean.next();
      const DrillingState st = sim.trajectory().at(a.t);
      const Eigen::Vector3d d = a.f - b.f;
      if (st.still) {
        ASSERT_EQ(d, Eigen::Vector3d::Zero());
        continue;
      }
      EXPECT_EQ(d.z(), 0.0);  // lateral only
      if (d.norm() > 0) ++shocked;
      if (st.drive == 1.0) {
        sum2 += d.head<2>().squaredNorm();
        ++cruising;
      }
    }
    if (shocks) {
      // About 0.5 / s over 660 s of drilling, 2 ms shocks stretched to two samples.
      EXPECT_GT(shocked, 300u);
      EXPECT_LT(shocked, 1000u);
    } else {
      EXPECT_NEAR(std::sqrt(sum2 / cruising / 2), 2.0, 0.05);
    }
  }
}

}  // namespace
}  // namespace plumb::sim
