// A family of the navigator's inputs over a Monte Carlo of seeds (ctest label `montecarlo`): how
// its scenario differs from the reference run and what the user gives, swept over seeds and scored
// pooled (families_monte_carlo_test.cpp, no_depth_families_monte_carlo_test.cpp).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drilling_support.hpp"

namespace plumb::strapdown::test {

inline constexpr int kSeeds = 8;

struct FamilyResult {
  double attitude_rms_z = 0, end_position_rms_z = 0;
  double angle_rms_z[3] = {0, 0, 0};  // inclination, azimuth, toolface
  double worst_attitude_deg = 0, worst_end_pct = 0;
  double worst_axis_deg = 0;  // the tool axis' direction: what position needs, near vertical too
  std::size_t fewest_valid_rows = 1u << 30;
  std::size_t most_invalid_rows = 0;  // rows before alignment, or that could not navigate
};

// A family: how its scenario differs from the reference (before the simulation), then its samples
// and the parameters the user gives (after).
struct Family {
  std::function<void(std::uint64_t seed, sim::DrillingScenario&)> scenario = [](std::uint64_t, sim::DrillingScenario&) {};
  std::function<void(std::uint64_t seed, std::vector<Sample>&, estimator::Parameters&)> input =
      [](std::uint64_t, std::vector<Sample>&, estimator::Parameters&) {};
  // The input's stamps are not the true instants: rows are scored at their sample's (its seq).
  bool restamped = false;
};

inline FamilyResult sweep(const char* name, const sim::ImuGrade& grade, double rate, const Family& family) {
  FamilyResult f;
  double att_z2 = 0, att_n = 0, end_z2 = 0, angle_z2[3] = {0, 0, 0}, angle_n[3] = {0, 0, 0};
  for (int k = 1; k <= kSeeds; ++k) {
    const auto seed = static_cast<std::uint64_t>(100 + k);
    auto scenario = sim::DrillingScenario::reference(grade, rate, seed);
    scenario.depth.sigma_m = 0;
    scenario.depth.quantum_m = 0;
    family.scenario(seed, scenario);
    estimator::Parameters params = parameters_for(scenario);
    sim::DrillingSimulator simulator(scenario);
    std::vector<TruthSample> truth;
    std::vector<Sample> samples = simulator.run(&truth);
    family.input(seed, samples, params);
    std::map<double, std::size_t> truth_index;
    if (family.restamped) {
      for (const Sample& x : samples) truth_index.emplace(x.t, static_cast<std::size_t>(x.seq));
    }
    const RunMetrics m = score_drilling(samples, truth, rate, simulator.trajectory().drilled_length_m(), params,
                                        nullptr, family.restamped ? &truth_index : nullptr);
    att_z2 += m.sum_z2;
    att_n += m.n_z;
    for (int a = 0; a < 3; ++a) {
      angle_z2[a] += m.sum_z2_angle[a];
      angle_n[a] += m.n_z_angle[a];
    }
    end_z2 += m.end_position_z2;
    f.worst_attitude_deg = std::max(f.worst_attitude_deg, m.max_attitude_err_deg());
    f.worst_end_pct = std::max(f.worst_end_pct, m.end_position_pct());
    f.worst_axis_deg = std::max(f.worst_axis_deg, m.max_axis_err_deg);
    f.fewest_valid_rows = std::min(f.fewest_valid_rows, m.valid_rows);
    f.most_invalid_rows = std::max(f.most_invalid_rows, m.rows - m.valid_rows);
  }
  f.attitude_rms_z = std::sqrt(att_z2 / att_n);
  for (int a = 0; a < 3; ++a) f.angle_rms_z[a] = angle_n[a] > 0 ? std::sqrt(angle_z2[a] / angle_n[a]) : 0.0;
  f.end_position_rms_z = std::sqrt(end_z2 / (3.0 * kSeeds));
  std::printf("%-34s worst attitude %.3f deg (axis %.3f), worst end position %.2f %% of MD, RMS(error/sigma) attitude "
              "%.2f (I %.2f A %.2f T %.2f), end position %.2f; fewest valid rows %zu\n",
              name, f.worst_attitude_deg, f.worst_axis_deg, f.worst_end_pct, f.attitude_rms_z, f.angle_rms_z[0],
              f.angle_rms_z[1], f.angle_rms_z[2], f.end_position_rms_z, f.fewest_valid_rows);
  return f;
}

// The targets: attitude RMS(error/sigma) within [0.7, 1.5], end position's at most 2. Where a
// family misses the end position's today, its measured level is the bound (a regression fails)
// and docs/navigator.md's known limits say so.
inline void expect_honest(const FamilyResult& f, double end_position_bound = 2.0) {
  EXPECT_GT(f.fewest_valid_rows, 850u);  // aligned in every run, without detector tuning
  EXPECT_GE(f.attitude_rms_z, 0.7);
  EXPECT_LE(f.attitude_rms_z, 1.5);
  EXPECT_LE(f.end_position_rms_z, end_position_bound);
}

}  // namespace plumb::strapdown::test
