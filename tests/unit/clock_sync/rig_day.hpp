// A synthetic rig day for the clock tests: stands drilled between connections, the depth reported on
// a rig clock with a known offset and drift, the tool's motion on the sensor clock, both with ramps
// (speed and rotation build up over ramp_s) and noise.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "plumb/clock_sync/clock_fit.hpp"
#include "plumb/clock_sync/depth_stillness.hpp"
#include "plumb/clock_sync/sensor_stillness.hpp"

namespace plumb::clock_sync::test {

struct RigDay {
  double offset_s = 320;      // depth clock - sensor clock at sensor time 0
  double drift = 50e-6;
  double hours = 12;
  double speed_mps = 30.0 / 3600;  // 30 m/h
  double ramp_s = 5;
  double depth_sd_m = 0.003;
  double depth_quantum_m = 0.01;   // WITS values with two decimals
  double depth_interval_s = 1;
  double block_s = 0.1;
  double blip_still = 0.002;       // chance that a still block reads moving (a knock)
  double blip_moving = 0.01;       // chance that a moving block reads still
  unsigned seed = 1;
  bool periodic = false;           // every stand and stop the same length

  struct Phase { double begin_s, end_s; bool drilling; };
  std::vector<Phase> phases;       // sensor clock

  void plan() {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> drill(900, 2400), stop(90, 400);
    double t = 0;
    phases.clear();
    bool drilling = false;
    while (t < hours * 3600) {
      const double d = periodic ? (drilling ? 1500 : 200) : (drilling ? drill(rng) : stop(rng));
      phases.push_back({t, t + d, drilling});
      t += d;
      drilling = !drilling;
    }
  }
  double depth_clock(double t_sensor) const { return t_sensor + offset_s + drift * t_sensor; }
  double sensor_clock(double t_depth) const { return (t_depth - offset_s) / (1 + drift); }
  // Speed fraction 0..1 in a phase: ramps at both ends of a drilling phase.
  double activity(double t) const {
    for (const auto& p : phases)
      if (t >= p.begin_s && t < p.end_s) {
        if (!p.drilling) return 0;
        return std::min({1.0, (t - p.begin_s) / ramp_s, (p.end_s - t) / ramp_s});
      }
    return 0;
  }
  // Depth at a sensor time: the integral of speed (fine steps are enough for a test).
  std::vector<std::pair<double, double>> depth_reports() const {
    std::mt19937 rng(seed + 1000);
    std::normal_distribution<double> noise(0, depth_sd_m);
    std::vector<std::pair<double, double>> out;
    const double dt = 0.01;
    double depth = 1000, t = 0;
    double next_report = depth_clock(0) + 0.37;  // the rig's frames are on its own clock
    const double end = hours * 3600;
    while (t < end) {
      depth += speed_mps * activity(t) * dt;
      t += dt;
      if (depth_clock(t) >= next_report) {
        double reading = depth + noise(rng);
        if (depth_quantum_m > 0) reading = std::round(reading / depth_quantum_m) * depth_quantum_m;
        out.emplace_back(next_report, reading);
        next_report += depth_interval_s;
      }
    }
    return out;
  }
  std::vector<std::pair<double, bool>> sensor_motion() const {
    std::mt19937 rng(seed + 2000);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<std::pair<double, bool>> out;
    for (double t = 0; t < hours * 3600; t += block_s) {
      bool moving = activity(t) > 0.01;  // a turning tool shows at once in its gyros and accelerometers
      if (!moving && u(rng) < blip_still) moving = true;
      else if (moving && u(rng) < blip_moving) moving = false;
      out.emplace_back(t, moving);
    }
    return out;
  }
  // The fit fed with both streams.
  ClockFit fit(ClockFitOptions o = {}) const {
    ClockFit f(o);
    // The tolerance above the depth's noise, as plumb-survey sets it (kStillSigmas).
    DepthStillnessOptions still;
    still.tolerance_m = std::max(0.02, 6.5 * depth_sd_m);
    DepthStillness depth(still);
    for (const auto& [t, d] : depth_reports())
      if (auto r = depth.add(t, d)) f.add_depth_run(*r);
    SensorStillness sensors;
    for (const auto& [t, m] : sensor_motion())
      if (auto r = sensors.add_motion(t, m)) f.add_sensor_run(*r);
    f.set_coverage(depth.first_t(), depth.settled_until(), sensors.first_t(), sensors.settled_until());
    return f;
  }
};

}  // namespace plumb::clock_sync::test
