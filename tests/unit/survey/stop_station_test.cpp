// A station from the whole stop: on simulated stops of 10 to 60 s, standing or turning at 30 rpm,
// with MEMS-grade noise, through the default estimator (compensated, 5 s windows) and the station
// detector fed the rig's depth as rigs report it (1 Hz, 3 cm of noise, quantized to 1 cm, held
// between reports), each station's error against the Cramer-Rao bound of the whole stop: RMS of
// error/bound at most 1.5 and no station beyond 4. (One window per station would sit at the bound
// of 5 s: sqrt(L / 5) times it.) Label `montecarlo`.
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/estimator/loader.hpp"
#include "plumb/sim/platform.hpp"
#include "plumb/survey/station_detector.hpp"
#include "plumb/windowed/cramer_rao.hpp"

namespace plumb::survey {
namespace {

struct Case {
  double stop_s, rpm, inclination_deg, azimuth_deg;
};

struct Outcome {
  std::vector<double> normalized;  // error / bound, inclination and azimuth
  std::size_t stations = 0;
};

Outcome run(const Case& c, std::uint64_t seed) {
  sim::Scenario s;
  s.g = 9.80665, s.total_b = 49, s.dip_deg = 62;
  s.inclination_deg = c.inclination_deg, s.azimuth_deg = c.azimuth_deg;
  s.toolface0_deg = std::fmod(137.50776405 * static_cast<double>(seed), 360.0);
  s.rotation.rpm = c.rpm;
  s.duration_s = c.stop_s;
  s.noise.sigma_accel = 0.015;  // MEMS accelerometers at 100 Hz
  s.noise.sigma_mag = 0.15;     // MEMS magnetometers, uT
  s.seed = seed;
  sim::PlatformSimulator simulator(s);
  const std::vector<Sample> samples = simulator.run();

  Outcome out;
  StationDetector detector({}, [&](const Station& st) {
    ++out.stations;
    windowed::CrbCase b;
    b.g = s.g, b.total_b = s.total_b, b.dip_deg = s.dip_deg;
    b.inclination_deg = c.inclination_deg, b.azimuth_deg = c.azimuth_deg, b.toolface0_deg = s.toolface0_deg;
    b.rpm = c.rpm, b.sigma_accel = 0.015, b.sigma_mag = 0.15, b.sample_rate_hz = 100, b.duration_s = c.stop_s;
    const windowed::CrbResult bound = windowed::cramer_rao_bound(b);
    out.normalized.push_back((st.inclination_deg - c.inclination_deg) / bound.inclination_deg);
    out.normalized.push_back(wrap_deg_180(st.magnetic_azimuth_deg - c.azimuth_deg) / bound.azimuth_deg);
  });
  // The rig: a report a second, 3 cm of noise, 1 cm steps, from before the stop to after it; then
  // the string moves on.
  std::mt19937 rng(static_cast<unsigned>(seed));
  std::normal_distribution<double> noise(0, 0.03);
  for (double t = -30; t <= c.stop_s + 2; t += 1)
    detector.add_depth({t, std::round((1234.5 + noise(rng)) * 100) / 100, 0, false});
  estimator::Runner runner = estimator::load_runner({"compensated"});
  runner.configure({}, 5.0);
  const auto take = [&](const estimator::Runner::Slot&, Estimate& e) { detector.add_attitude(e, ""); };
  runner.push(samples, take);
  runner.flush(take);
  detector.add_depth({c.stop_s + 3, 1236, 0, false});
  detector.flush();
  return out;
}

TEST(StopStation, WholeStopSitsAtTheBoundOfItsLength) {
  const Case cases[] = {{10, 0, 30, 120}, {20, 0, 85, 10}, {60, 0, 55, 250}, {10, 30, 60, 300},
                        {30, 30, 20, 45},  {60, 30, 88, 170}};
  double sum_sq = 0, worst = 0;
  std::size_t n = 0;
  for (const Case& c : cases) {
    double case_sq = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      const Outcome o = run(c, seed);
      ASSERT_EQ(o.stations, 1u) << c.stop_s << " s stop at " << c.rpm << " rpm, seed " << seed;
      for (double v : o.normalized) {
        case_sq += v * v;
        worst = std::max(worst, std::abs(v));
      }
      n += o.normalized.size();
    }
    sum_sq += case_sq;
    std::printf("%2.0f s stop, %2.0f rpm, I %2.0f: RMS(error/bound) %.2f\n", c.stop_s, c.rpm, c.inclination_deg,
                std::sqrt(case_sq / 16));
  }
  const double rms = std::sqrt(sum_sq / static_cast<double>(n));
  std::printf("%zu station angles: RMS(error / bound of the whole stop) %.2f, worst %.2f\n", n, rms, worst);
  EXPECT_LE(rms, 1.5);
  EXPECT_LE(worst, 4.0);
}

}  // namespace
}  // namespace plumb::survey
