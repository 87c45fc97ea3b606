// The drilling tool's temperature (tool_temperature.hpp) against what it means: the tool warms
// toward the formation at stops and cools toward the mud while drilling, by first-order lags of the
// stated time constants; the sensor reads it within its noise and step; the biases follow it by the
// run's drawn coefficients exactly, the rest of every sample (noise included) unchanged; the drawn
// coefficients spread about the grade's stated ones. Off by default: no temperature, as before.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/sim/drilling.hpp"

namespace plumb::sim {
namespace {

// Stops of 5 min (a slow connection) between 3 min drilling segments: long enough for the swing
// to reach most of its 30 degC.
DrillingScenario temperature_run(const ImuGrade& grade, bool enabled, std::uint64_t seed = 7) {
  DrillingScenario sc = DrillingScenario::reference(grade, 50, seed);
  sc.plan.segments = {DrillSegment::drill(9, 0.05), DrillSegment::stop(300), DrillSegment::rotary(9, 0.05, 30),
                      DrillSegment::stop(300), DrillSegment::drill(9, 0.05)};
  sc.temperature.enabled = enabled;
  return sc;
}

TEST(DrillingTemperature, OffByDefaultGivesNoTemperature) {
  EXPECT_FALSE(DrillingScenario().temperature.enabled);
  DrillingSimulator sim(DrillingScenario::reference(ImuGrade::mems(), 100, 3));
  for (int k = 0; k < 500; ++k) {
    const Sample s = sim.next();
    EXPECT_FALSE(s.flags & flags::kHasTemperature);
    EXPECT_EQ(s.temp_c, 0.0);
  }
}

TEST(DrillingTemperature, WarmsAtStopsAndCoolsWhileDrillingByItsLags) {
  const DrillingScenario sc = temperature_run(ImuGrade::tactical(), true);
  const DrillingSimulator sim(sc);
  const ToolTemperature& m = sc.temperature;
  const auto& phases = sim.trajectory().phases();
  double prev = sim.temperature_at(0.0), low = prev, high = prev;
  for (const auto& ph : phases) {
    const double start = sim.temperature_at(ph.t0), end = sim.temperature_at(ph.t1 - 1e-9);
    const double target = ph.moving ? m.circulating_c : m.formation_c;
    const double tau = ph.moving ? m.cool_tau_s : m.heat_tau_s;
    // The lag's own law over the phase, from where it started.
    EXPECT_NEAR(end, target + (start - target) * std::exp(-(ph.t1 - ph.t0) / tau), 1e-6);
    if (ph.moving) {
      EXPECT_LT(end, start);
    } else {
      EXPECT_GT(end, start);
    }
    EXPECT_NEAR(start, prev, 1e-6);  // continuous across phases
    prev = end;
    low = std::min(low, end);
    high = std::max(high, end);
  }
  // Tens of degrees: a 5 min stop reaches 1 - exp(-2.5) = 92 % of the way to the formation.
  EXPECT_GT(high - low, 20.0);
  EXPECT_LT(high, m.formation_c + 1e-9);
  EXPECT_GT(low, m.circulating_c - 1e-9);
}

TEST(DrillingTemperature, SensorReadsTheTruthWithinItsNoiseAndStep) {
  const DrillingScenario sc = temperature_run(ImuGrade::tactical(), true);
  DrillingSimulator sim(sc);
  double sum = 0, sum2 = 0;
  std::size_t n = 0;
  while (!sim.done()) {
    const double t = sim.time_of(sim.index());
    const Sample s = sim.next();
    ASSERT_TRUE(s.flags & flags::kHasTemperature);
    const double q = sc.temperature.sensor_quantum_c;
    EXPECT_NEAR(std::remainder(s.temp_c, q), 0.0, 1e-9);  // on the sensor's steps
    const double e = s.temp_c - sim.temperature_at(t);
    sum += e;
    sum2 += e * e;
    ++n;
  }
  const double mean = sum / n, rms = std::sqrt(sum2 / n);
  const double expected = std::hypot(sc.temperature.sensor_sigma_c, sc.temperature.sensor_quantum_c / std::sqrt(12.0));
  EXPECT_NEAR(mean, 0.0, 0.005);
  EXPECT_NEAR(rms, expected, 0.1 * expected);
}

TEST(DrillingTemperature, BiasesFollowTheDrawnCoefficientsExactly) {
  DrillingSimulator warm(temperature_run(ImuGrade::mems(), true)), plain(temperature_run(ImuGrade::mems(), false));
  EXPECT_EQ(warm.gyro_bias(), plain.gyro_bias());
  EXPECT_EQ(warm.accel_bias(), plain.accel_bias());
  double largest_shift = 0;
  while (!warm.done()) {
    const double t = warm.time_of(warm.index());
    const Sample a = warm.next(), b = plain.next();
    const double dT = warm.temperature_at(t) - warm.scenario().temperature.start_c;
    // Everything else (noise, field, depth) is the same sample.
    EXPECT_EQ(a.b, b.b);
    EXPECT_EQ(a.depth_m, b.depth_m);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(a.w[i] - b.w[i], dT * warm.gyro_bias_temp()[i], 1e-15);
      EXPECT_NEAR(a.f[i] - b.f[i], dT * warm.accel_bias_temp()[i], 1e-12);
    }
    largest_shift = std::max(largest_shift, std::abs(dT * warm.gyro_bias_temp()[0]));
  }
  // MEMS 0.2 deg/h/degC over a swing of over 20 degC: several deg/h.
  EXPECT_GT(largest_shift * 180.0 / 3.14159265358979 * 3600.0, 2.0);
}

TEST(DrillingTemperature, CoefficientsSpreadAboutTheStatedOnes) {
  const ImuGrade grade = ImuGrade::tactical();
  double sum = 0, sum2 = 0;
  int n = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const DrillingSimulator sim(temperature_run(grade, true, seed));
    for (int i = 0; i < 3; ++i) {
      const double g = sim.gyro_bias_temp()[i] / grade.gyro_bias_temp();
      const double a = sim.accel_bias_temp()[i] / grade.accel_bias_temp();
      sum += g + a;
      sum2 += (g - 1) * (g - 1) + (a - 1) * (a - 1);
      n += 2;
    }
  }
  // Drawn as stated x (1 + 0.25 N(0, 1)): 1200 draws give the mean within 0.03 and the spread within 10 %.
  EXPECT_NEAR(sum / n, 1.0, 0.03);
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.25, 0.025);
}

}  // namespace
}  // namespace plumb::sim
