// Test support: turntable recordings as calibration inputs, truth comparisons, inclination sweeps.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "plumb/calibration/procedures.hpp"
#include "plumb/calibration/types.hpp"
#include "plumb/core/attitude.hpp"
#include "plumb/sim/turntable.hpp"

namespace plumb::test {

inline std::vector<calibration::Station> stations_of(const sim::Recording& rec) {
  std::vector<calibration::Station> out;
  for (const auto& s : rec.stations) {
    calibration::Station st;
    st.name = s.plan.name;
    st.start_s = s.start_s;
    st.end_s = s.end_s;
    st.orientation = calibration::parse_orientation(s.plan.orientation);
    st.run = s.plan.run;
    st.reference_temps_c = s.reference_temps_c;
    out.push_back(st);
  }
  return out;
}

// Every named parameter within k of its own standard deviation from the truth; returns how many
// were checked.
inline int expect_within_sd(const calibration::Result& r, const std::string& name, double truth, double k = 3.0) {
  const auto* p = calibration::find_parameter(r, name);
  EXPECT_NE(p, nullptr) << name;
  if (!p) return 0;
  EXPECT_GT(p->sd, 0.0) << name;
  EXPECT_LE(std::abs(p->value - truth), k * p->sd)
      << name << ": estimate " << p->value << " truth " << truth << " sd " << p->sd << " (error "
      << (p->value - truth) / p->sd << " sd)";
  return 1;
}

inline int expect_triad_within_sd(const calibration::Result& r, const std::string& prefix, const TriadModel& t,
                                  bool second_order = true) {
  const char* const ax = "xyz";
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    n += expect_within_sd(r, prefix + "bias." + ax[i], t.bias[i]);
    for (int j = 0; j < 3; ++j) n += expect_within_sd(r, prefix + "sensitivity." + ax[i] + ax[j], t.sensitivity(i, j));
    if (second_order) n += expect_within_sd(r, prefix + "second_order." + ax[i], t.second_order[i]);
  }
  return n;
}

// Largest inclination error (deg) of a model over a grid of orientations and temperatures, using
// the package's exact (noise-free) raw outputs.
inline double max_inclination_error(const sim::SensorPackage& pkg, const CalibrationModel& model,
                                    const std::vector<double>& temperatures, double g = 9.80665) {
  double worst = 0;
  for (double T : temperatures)
    for (double inc = 0; inc <= 180; inc += 7.5)
      for (double tf = 0; tf < 360; tf += 30) {
        const Eigen::Vector3d f = -gravity_tool(inc * kDeg, tf * kDeg, g);
        Sample s;
        s.f = pkg.raw_accel(f, T);
        s.b = pkg.raw_mag(Eigen::Vector3d(20, 0, 40), T);
        s.temp_c = pkg.raw_temperature(T);
        s.flags = flags::kHasTemperature;
        model.apply(s);
        const double est = std::atan2(std::hypot(s.f.x(), s.f.y()), -s.f.z()) / kDeg;
        worst = std::max(worst, std::abs(est - inc));
      }
  return worst;
}

inline void print_outcome_warnings(const calibration::Outcome& o) {
  for (const auto& w : o.warnings) std::printf("  warning: %s\n", w.c_str());
}

}  // namespace plumb::test
