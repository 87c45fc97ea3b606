// The walk simulator's physics: its angular rate, velocity and acceleration are the derivatives of
// its attitude and position, the foot stands exactly still on every footprint, and the loop closes.
#include <cmath>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/walk.hpp"
#include "error_free.hpp"
#include "cross_matrix.hpp"

namespace plumb::sim {
namespace {

// dC_n^b/dt = -[w_nb x] C_n^b, so [w_nb x] = -(dC/dt) C^T; central differences of h = 1e-5 s leave
// h^2/6 |C'''| ~ 1e-10 x (rates up to 7 rad/s)^3 plus round-off 1e-16 / h: below 1e-7 either way.
TEST(WalkPhysics, RatesAreTheDerivativesOfAttitudeAndPosition) {
  const WalkPath path(WalkScenario::loop_60m());
  const double h = 1e-5;
  double max_rate = 0, max_accel = 0;
  int checked = 0;
  for (const auto& swing : path.swings())
    for (double frac : {0.013, 0.25, 0.4, 0.5, 0.61, 0.9, 0.997}) {
      const double t = swing.t0 + frac * (swing.t1 - swing.t0);
      const WalkState st = path.at(t), a = path.at(t - h), b = path.at(t + h);
      const Eigen::Matrix3d w_fd = -(b.c_nb - a.c_nb) / (2 * h) * st.c_nb.transpose();
      EXPECT_LT((w_fd - test::cross_matrix(st.w_nb)).cwiseAbs().maxCoeff(), 1e-7) << "t " << t;
      EXPECT_LT((st.velocity - (b.position - a.position) / (2 * h)).norm(), 1e-7) << "t " << t;
      EXPECT_LT((st.acceleration - (b.velocity - a.velocity) / (2 * h)).norm(), 1e-6) << "t " << t;
      max_rate = std::max(max_rate, st.w_nb.norm());
      max_accel = std::max(max_accel, st.acceleration.norm());
      ++checked;
    }
  EXPECT_EQ(checked, 7 * static_cast<int>(path.swings().size()));
  // A walk, not a crawl: the foot turns at hundreds of deg/s and accelerates at more than 1 g.
  EXPECT_GT(max_rate, 3.0);
  EXPECT_GT(max_accel, 10.0);
}

// Between swings the state is a footprint's: no velocity, no acceleration, no rotation, so an
// error-free IMU reads exactly the earth rate and -G, and the truth does not move at all.
TEST(WalkPhysics, StanceIsExactlyStill) {
  const WalkScenario scenario = test::error_free(WalkScenario::loop_25m());
  WalkSimulator sim(scenario);
  std::vector<TruthSample> truth;
  const std::vector<Sample> s = sim.run(&truth);
  const Eigen::Vector3d w_ie = 7.292115e-5 * Eigen::Vector3d(std::cos(35 * kDeg), 0.0, -std::sin(35 * kDeg));
  std::size_t still = 0;
  std::set<std::size_t> footprints_stood_on;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (!sim.still_at(s[k].t)) continue;
    ++still;
    const WalkState st = sim.path().at(s[k].t);
    footprints_stood_on.insert(st.stride);
    EXPECT_TRUE(st.still);
    EXPECT_EQ(st.velocity, Eigen::Vector3d::Zero());
    EXPECT_EQ(st.acceleration, Eigen::Vector3d::Zero());
    EXPECT_EQ(st.w_nb, Eigen::Vector3d::Zero());
    EXPECT_LT((s[k].w - st.c_nb * w_ie).norm(), 1e-18);
    EXPECT_LT((s[k].f + st.c_nb * Eigen::Vector3d(0, 0, scenario.g)).norm(), 1e-14);
    EXPECT_EQ(truth[k].vn_mps, 0.0);
    EXPECT_EQ(truth[k].ve_mps, 0.0);
    EXPECT_EQ(truth[k].vd_mps, 0.0);
    // A flat foot: the tool lies horizontal with its x axis up.
    EXPECT_NEAR(truth[k].inclination_deg, 90.0, 1e-12);
    EXPECT_NEAR(std::remainder(truth[k].toolface_deg, 360.0), 0.0, 1e-12);
    if (k > 0 && sim.still_at(s[k - 1].t) && sim.path().at(s[k - 1].t).stride == st.stride) {
      EXPECT_EQ(truth[k].north_m, truth[k - 1].north_m);
      EXPECT_EQ(truth[k].east_m, truth[k - 1].east_m);
      EXPECT_EQ(truth[k].down_m, truth[k - 1].down_m);
    }
  }
  // Every footprint is stood on, the first and the last for the alignment and the end.
  EXPECT_EQ(footprints_stood_on.size(), sim.path().footprints().size());
  EXPECT_GT(still, static_cast<std::size_t>(15 * 400));
}

// A walk's stance periods: 0.05 to 0.3 s, drawn per stride from the seed, the same at any rate;
// at 400 Hz even the shortest stance holds 20 samples.
TEST(WalkPhysics, StancesLastFromFiftyToThreeHundredMilliseconds) {
  const WalkPath path(WalkScenario::loop_60m());
  const WalkPath other_rate(WalkScenario::loop_60m(ImuGrade::perfect(), 100));
  const WalkPath other_seed(WalkScenario::loop_60m(ImuGrade::mems(), 400, 2));
  const auto& sw = path.swings();
  ASSERT_EQ(sw.size(), 2u * (5 + 9 + 5 + 7));
  double shortest = 1, longest = 0;
  for (std::size_t k = 1; k < sw.size(); ++k) {
    const double stance = sw[k].t0 - sw[k - 1].t1;
    shortest = std::min(shortest, stance);
    longest = std::max(longest, stance);
    EXPECT_EQ(sw[k].t0, other_rate.swings()[k].t0);
  }
  EXPECT_GE(shortest, 0.05);
  EXPECT_LE(longest, 0.3);
  EXPECT_LT(shortest, 0.08);   // the draws cover the range
  EXPECT_GT(longest, 0.27);
  EXPECT_NE(sw.back().t1, other_seed.swings().back().t1);
  EXPECT_DOUBLE_EQ(sw.front().t0, 10.0);
  EXPECT_NEAR(path.duration_s() - sw.back().t1, 5.0, 1e-12);
}

// The loop closes exactly: the last footprint is the first, with the heading one turn further.
TEST(WalkPhysics, TheLoopCloses) {
  for (const WalkScenario& scenario : {WalkScenario::loop_25m(), WalkScenario::loop_60m()}) {
    WalkSimulator sim(test::error_free(scenario));
    std::vector<TruthSample> truth;
    sim.run(&truth);
    const TruthSample &start = truth.front(), &end = truth.back();
    EXPECT_LT(std::hypot(end.north_m - start.north_m, end.east_m - start.east_m, end.down_m - start.down_m), 1e-9);
    EXPECT_NEAR(std::remainder(end.azimuth_deg - start.azimuth_deg, 360.0), 0.0, 1e-9);
    EXPECT_NEAR(end.inclination_deg, start.inclination_deg, 1e-12);
    const auto& f = sim.path().footprints();
    EXPECT_NEAR(f.back().heading - f.front().heading, 2 * kPi, 1e-12);
  }
}

// The named loops: 25 m flat, 60 m with a flight of 3 m up and back down, strides near 1.4 m.
TEST(WalkPhysics, NamedLoopsHaveTheirLengthAndHeight) {
  const WalkPath short_loop(WalkScenario::loop_25m());
  EXPECT_NEAR(short_loop.horizontal_length_m(), 25.0, 1e-9);
  EXPECT_NEAR(short_loop.length_m(), 25.0, 1e-9);
  EXPECT_EQ(short_loop.swings().size(), 18u);
  const WalkPath long_loop(WalkScenario::loop_60m());
  EXPECT_NEAR(long_loop.horizontal_length_m(), 60.0, 1e-9);
  EXPECT_GT(long_loop.length_m(), 61.0);
  double highest = 0;
  for (const auto& f : long_loop.footprints()) highest = std::min(highest, f.position.z());
  EXPECT_NEAR(highest, -3.0, 1e-12);
  for (std::size_t k = 1; k < long_loop.footprints().size(); ++k) {
    const auto& f = long_loop.footprints();
    const double stride = (f[k].position - f[k - 1].position).head<2>().norm();
    EXPECT_TRUE(std::abs(stride - 0.6) < 1e-9 || (stride > 1.2 && stride < 1.6)) << stride;
  }
}

TEST(WalkPhysics, BadLoopsAreRefusedWithAReason) {
  WalkScenario open = WalkScenario::loop_25m();
  open.legs.pop_back();
  EXPECT_THROW(WalkPath{open}, std::invalid_argument);
  WalkScenario fast = WalkScenario::loop_25m();
  fast.cadence_hz = 3;
  EXPECT_THROW(WalkPath{fast}, std::invalid_argument);
  WalkScenario stance = WalkScenario::loop_25m();
  stance.stance_min_s = 0;
  EXPECT_THROW(WalkPath{stance}, std::invalid_argument);
  EXPECT_THROW(WalkScenario::loop(10, 5), std::invalid_argument);  // 15 stair strides: 9 m > a 3.3 m side
  WalkScenario rate = WalkScenario::loop_25m();
  rate.sample_rate_hz = 0;
  EXPECT_THROW(WalkSimulator{rate}, std::invalid_argument);
  try {
    WalkPath{open};
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("from the start"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plumb::sim
