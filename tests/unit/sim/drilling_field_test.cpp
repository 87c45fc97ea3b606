// The drilling simulator's field options against what each means: shocks of tens of g clipped at
// the accelerometers' range (the clipped samples sit at it, flagged; without a range they go
// beyond), and stick-slip (the spin rate swings by the amplitude asked, the toolface at the
// segment's end is the steady spin's, the rate is the toolface's derivative, and a gyro range
// below its peak clips it). Off by default: the same samples as before.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/drilling.hpp"

namespace plumb::sim {
namespace {

constexpr double kFieldG = 9.80665;

DrillingScenario field_shocks(double range_g) {
  DrillingScenario sc = DrillingScenario::reference(ImuGrade::mems(), 100, 3);
  sc.vibration.shock_rate_hz = 0.5;
  sc.vibration.shock_peak = 40 * kFieldG;
  sc.grade.accel_range_g = range_g;
  return sc;
}

TEST(DrillingField, ShocksClipAtTheAccelerometerRange) {
  DrillingSimulator unlimited(field_shocks(0)), clipped(field_shocks(16));
  std::size_t at_range = 0, beyond_without = 0;
  while (!clipped.done()) {
    const Sample a = unlimited.next(), b = clipped.next();
    for (int i = 0; i < 3; ++i) {
      if (std::abs(a.f[i]) > 16 * kFieldG) {
        ++beyond_without;
        // Clipped: exactly at the range, on the side of the truth, and flagged.
        EXPECT_EQ(b.f[i], std::copysign(16 * kFieldG, a.f[i]));
        EXPECT_TRUE(b.flags & flags::kAccelSaturated);
        ++at_range;
      } else {
        EXPECT_EQ(b.f[i], a.f[i]);
      }
    }
    EXPECT_LE(b.f.cwiseAbs().maxCoeff(), 16 * kFieldG);
  }
  // 0.5 shocks/s over 660 s of drilling, 40 g peaks of two samples: hundreds beyond 16 g.
  EXPECT_GT(beyond_without, 100u);
  EXPECT_EQ(at_range, beyond_without);
}

// A rebounding shock is the tool struck out to the wall and back: what it adds to the readings
// integrates to no velocity and no displacement (the truth's path carries no shocks). Checked on
// the first segment, a slide (the tool's frame does not turn, so the readings' sums are the
// motion's): 30 g shocks, 0.3 a second, unclipped. (A full sine cycle of acceleration comes back in
// velocity only and leaves 7.5 cm per shock at 100 Hz: metres over the segment.)
TEST(DrillingField, ReboundingShocksComeBackInVelocityAndPosition) {
  auto with = DrillingScenario::reference(ImuGrade::tactical(), 100, 7), without = with;
  with.vibration.shock_rate_hz = 0.3;
  with.vibration.shock_peak = 30 * kFieldG;
  with.vibration.shock_rebounds = true;
  std::vector<TruthSample> truth;
  const std::vector<Sample> a = DrillingSimulator(with).run(&truth), b = DrillingSimulator(without).run();
  ASSERT_EQ(a.size(), b.size());
  const double dt = 0.01;
  const auto sliding = [&](std::size_t i) {
    return truth[i].rpm == 0 && std::hypot(truth[i].vn_mps, truth[i].ve_mps, truth[i].vd_mps) > 0;
  };
  std::size_t k = 0, shocks = 0;
  while (k < truth.size() && !sliding(k)) ++k;
  double worst_v = 0, worst_x = 0, largest = 0;
  while (k < truth.size() && sliding(k)) {
    if ((a[k].f - b[k].f).norm() == 0) {
      ++k;
      continue;
    }
    // One shock: the velocity and the displacement it adds, from its first reading to its last.
    Eigen::Vector3d v = Eigen::Vector3d::Zero(), x = Eigen::Vector3d::Zero();
    for (; k < truth.size() && sliding(k) && (a[k].f - b[k].f).norm() > 0; ++k) {
      largest = std::max(largest, (a[k].f - b[k].f).norm());
      v += (a[k].f - b[k].f) * dt;
      x += v * dt;
    }
    ++shocks;
    worst_v = std::max(worst_v, v.norm());
    worst_x = std::max(worst_x, x.norm());
  }
  EXPECT_GT(shocks, 20u);
  EXPECT_GT(largest, 10 * kFieldG) << "the slide had shocks of tens of g";
  EXPECT_LT(worst_v, 1e-6) << "no velocity left after a shock";
  // The readings' sums, four per shock, leave the samples' own discretisation (below a centimetre);
  // a full sine cycle of acceleration left 7.5 cm each.
  EXPECT_LT(worst_x, 0.01) << "no displacement left after a shock";
}

TEST(DrillingField, RangesOffByDefaultLeaveTheSamplesAsBefore) {
  EXPECT_EQ(ImuGrade::mems().accel_range_g, 0.0);
  EXPECT_EQ(DrillingPlan().stick_slip_rpm, 0.0);
  EXPECT_FALSE(std::isfinite(ImuGrade::mems().accel_range()));
}

DrillingScenario stick_slip_run(double amplitude_rpm) {
  DrillingScenario sc = DrillingScenario::survey_stop_and_go(ImuGrade::perfect(), 100, 1);
  sc.plan.stick_slip_rpm = amplitude_rpm;
  sc.plan.stick_slip_period_s = 4;
  return sc;
}

TEST(DrillingField, StickSlipSwingsTheSpinAndKeepsTheSegmentEnds) {
  const DrillingTrajectory steady(stick_slip_run(0).plan), slipping(stick_slip_run(150).plan);
  double peak_rpm = 0, low_rpm = 1e9;
  for (const auto& ph : slipping.phases()) {
    // Each phase ends where the steady spin's does (the swing fades with the drive).
    const DrillingState a = steady.at(ph.t1), b = slipping.at(ph.t1);
    EXPECT_NEAR(b.toolface, a.toolface, 1e-9);
    if (!ph.moving) continue;
    for (double t = ph.t0 + ph.ramp + 0.005; t < ph.t1 - ph.ramp; t += 0.01) {
      const double rpm = slipping.at(t).toolface_rate * 60 / (2 * kPi);
      peak_rpm = std::max(peak_rpm, rpm);
      low_rpm = std::min(low_rpm, rpm);
      // The rate is the toolface's derivative.
      const double h = 1e-4;
      const double numeric = (slipping.at(t + h).toolface - slipping.at(t - h).toolface) / (2 * h);
      ASSERT_NEAR(slipping.at(t).toolface_rate, numeric, 1e-6) << t;
    }
  }
  // 60 rpm +- 150 rpm while cruising.
  EXPECT_NEAR(peak_rpm, 210, 1);
  EXPECT_NEAR(low_rpm, -90, 1);
}

TEST(DrillingField, StickSlipPastTheGyroRangeClipsIt) {
  DrillingScenario sc = stick_slip_run(150);
  sc.grade.gyro_range_deg_s = 1000;  // the slip's 210 rpm is 1260 deg/s
  std::size_t clipped = 0;
  for (const Sample& s : DrillingSimulator(sc).run()) {
    EXPECT_LE(std::abs(s.w.z()), 1000 * kDeg * (1 + 1e-15));
    if (std::abs(s.w.z()) >= 1000 * kDeg) ++clipped;
  }
  EXPECT_GT(clipped, 1000u);
}

}  // namespace
}  // namespace plumb::sim

namespace plumb::sim {
namespace {

// Heave on the measured depth only: the depth swings by the amplitude at the period about the
// truth, the IMU's samples and the truth are those of the run without it.
TEST(DrillingField, HeaveIsOnTheDepthOnly) {
  DrillingScenario calm = DrillingScenario::reference(ImuGrade::mems(), 100, 6);
  DrillingScenario heaving = calm;
  heaving.depth.heave_amplitude_m = 0.3;
  heaving.depth.heave_period_s = 12;
  DrillingSimulator a(calm), b(heaving);
  double lo = 1e9, hi = -1e9;
  std::size_t zero_crossings = 0;
  double last = 0;
  while (!a.done()) {
    TruthSample ta, tb;
    const Sample sa = a.next(&ta), sb = b.next(&tb);
    ASSERT_EQ(sa.f, sb.f);
    ASSERT_EQ(sa.w, sb.w);
    ASSERT_EQ(ta.north_m, tb.north_m);
    const double residual = sb.depth_m - sa.depth_m;
    lo = std::min(lo, residual);
    hi = std::max(hi, residual);
    if (sa.t > 0 && (residual > 0) != (last > 0)) ++zero_crossings;
    last = residual;
  }
  EXPECT_NEAR(hi, 0.3, 1e-3);
  EXPECT_NEAR(lo, -0.3, 1e-3);
  // Two crossings per 12 s period over the 960 s run.
  EXPECT_NEAR(static_cast<double>(zero_crossings), 2 * 960 / 12.0, 2);
}

}  // namespace
}  // namespace plumb::sim
