// Running the procedures on source-form packages (source_form_package.hpp) and judging the result
// against the package's truth.
#pragma once

#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/calibration/procedures.hpp"
#include "source_form_package.hpp"

namespace plumb::test::source {

struct Trial {
  calibration::Outcome outcome;
  double before_deg = 0;   // worst true inclination error, nominal conversion
  double after_deg = -1;   // worst true inclination error with the coefficients (-1: none written)
};

// 200 orientations that are not stations, inclination 0..120 deg, at temperatures spread over
// [t_min, t_max] (true temperatures).
inline void judge(Trial& trial, const Package& pkg, std::mt19937_64& rng, double t_min, double t_max) {
  const auto orientations = random_orientations(rng, 200, 120);
  std::uniform_real_distribution<double> temp(t_min, t_max);
  std::vector<double> temps;
  for (int i = 0; i < 200; ++i) temps.push_back(temp(rng));
  temps.front() = t_min;   // the ends of the range are where a polynomial goes wrong first
  temps.back() = t_max;
  trial.before_deg = worst_inclination_error(pkg, nominal_model(pkg), orientations, temps);
  if (trial.outcome.ok())
    trial.after_deg = worst_inclination_error(pkg, trial.outcome.result->model, orientations, temps);
}

inline Trial six_position_trial(const Package& pkg, const Rig& rig, std::vector<Position> positions, std::uint64_t seed) {
  const Recording rec = record(pkg, rig, positions, seed);
  calibration::CommonOptions opt;
  opt.nominal = nominal_model(pkg);
  Trial trial;
  trial.outcome = calibration::six_position(rec.samples, rec.stations, opt);
  std::mt19937_64 rng(seed + 1000);
  // The stations' temperature: a 6-position calibration has no temperature terms.
  judge(trial, pkg, rng, positions.front().temperature_c, positions.front().temperature_c);
  return trial;
}

inline Trial twenty_four_trial(const Package& pkg, const Rig& rig, const std::vector<double>& temps, double station_s,
                               std::uint64_t seed, int order = 0) {
  const Recording rec = record(pkg, rig, twenty_four_positions(temps, station_s), seed);
  calibration::TwentyFourOptions opt;
  opt.nominal = nominal_model(pkg);
  opt.temperature_order = order;
  Trial trial;
  trial.outcome = calibration::twenty_four_position(rec.samples, rec.stations, opt);
  std::mt19937_64 rng(seed + 1000);
  judge(trial, pkg, rng, temps.front(), temps.back());
  return trial;
}

// A run that writes coefficients must be within the tolerance and its true error within twice
// its own prediction; a refused run names what it refused.
inline void expect_honest(const Trial& t, const std::string& what, double max_true_deg) {
  if (!t.outcome.ok()) return;
  const auto& p = t.outcome.result->predicted;
  ASSERT_TRUE(p.valid) << what;
  EXPECT_LE(t.after_deg, max_true_deg) << what;
  EXPECT_LE(t.after_deg, 2 * p.inclination_deg) << what << ": true " << t.after_deg << " deg, predicted "
                                                << p.inclination_deg << " deg";
}

}  // namespace plumb::test::source
