// Side-by-side comparison of estimator plugins on simulated data (`plumb compare`).
// A grid of cases (inclination x speed x accelerometer SNR; the reference grid of docs/conventions.md by
// default) is swept over azimuth with several Monte Carlo seeds per azimuth; each record is one
// estimator window. Per case and plugin: RMS and maximum azimuth and inclination errors beside the
// Cramer-Rao bound, and the error per azimuth (for the paper-style plot).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "plumb/estimator/estimator.hpp"
#include "plumb/sim/platform.hpp"

namespace plumb::compare {

struct CompareConfig {
  std::vector<std::string> plugins{"static", "integral", "compensated"};
  // --param assignments, [PLUGIN.]KEY=VALUE (estimator/assignments.hpp); `window` is 0 (one record).
  std::vector<std::string> assignments;
  // The grid. Every combination of these is one case.
  std::vector<double> inclinations_deg{0.5, 1, 2};
  std::vector<double> rpms{0, 60, 120};
  std::vector<double> snr_accel_db{10, 20};
  double snr_mag_db = 20;
  std::vector<double> azimuths_deg;  // empty: 0, 10, ..., 350
  int seeds = 4;                     // Monte Carlo records per azimuth
  std::uint64_t base_seed = 1;
  // Everything else of the scenario (g, field, dip, rate, duration, sensor errors, vibration) comes
  // from here; inclination, azimuth, speed, SNRs and seed are set per record. When `profile` is not
  // Constant, it is used with its rpm replaced by each grid speed (mean speed).
  sim::Scenario base = sim::Scenario::reference(1, 0, 0, 10);
  // Turn each record's start toolface with the seed, so records do not all start alike.
  bool vary_toolface = true;

  // Keep base.noise as given (sigmas or SNRs) instead of applying snr_accel_db / snr_mag_db;
  // snr_accel_db then only labels the case.
  bool use_base_noise = false;

  static CompareConfig reference_grid() { return {}; }
  // One scenario exactly as given (inclination, azimuth, rotation profile, noise, sensor errors):
  // a one-case, one-azimuth grid; raise `seeds` for Monte Carlo statistics.
  static CompareConfig single(const sim::Scenario& scenario, int seeds = 20);
  // The default azimuth sweep when azimuths_deg is empty.
  std::vector<double> azimuth_sweep() const;
};

struct AzimuthPoint {
  double azimuth_deg = 0;
  double mean_azimuth_error_deg = 0;      // over the valid records at this azimuth
  double mean_inclination_error_deg = 0;
  double rms_azimuth_error_deg = 0;
  double rms_inclination_error_deg = 0;
  double crb_azimuth_deg = 0;
  double crb_inclination_deg = 0;
  int valid = 0;
  int records = 0;
};

struct PluginCaseResult {
  std::string plugin;
  double rms_azimuth_error_deg = 0;       // over all valid records of the case
  double max_azimuth_error_deg = 0;       // largest |error|
  double rms_inclination_error_deg = 0;
  double max_inclination_error_deg = 0;
  double mean_azimuth_sd_deg = 0;         // the plugin's own reported standard deviation, RMS
  // Coverage, whether the reported standard deviations are honest: RMS of error / reported sd over the valid records with a reported sd;
  // 1 when the sd is honest, above 1 when it is too small. 0 when the plugin reports no sd.
  double azimuth_coverage = 0, inclination_coverage = 0;
  // Azimuth-dependent bias: least-squares fit of the mean azimuth error to a + b sinA + c cosA.
  double bias_sin_deg = 0, bias_cos_deg = 0, bias_mean_deg = 0;
  int valid = 0;                          // records with a valid azimuth
  int records = 0;
  std::string first_invalid_reason;
  std::vector<AzimuthPoint> by_azimuth;
};

struct CaseResult {
  double inclination_deg = 0;
  double rpm = 0;
  double snr_accel_db = 0;
  double snr_mag_db = 0;
  double sigma_accel = 0;                 // m/s^2 (at the first azimuth)
  double sigma_mag = 0;                   // uT
  double crb_azimuth_deg = 0;             // RMS over the azimuth sweep of the per-azimuth bound
  double crb_inclination_deg = 0;
  std::vector<PluginCaseResult> plugins;

  const PluginCaseResult* find(const std::string& plugin) const;
};

struct CompareResult {
  std::vector<std::string> plugins;
  std::vector<CaseResult> cases;
  std::size_t records = 0;                // simulated records (each run through every plugin)
  double seconds = 0;                     // wall time
};

// done, total records; called after each record. Return value ignored.
using ProgressCallback = std::function<void(std::size_t done, std::size_t total)>;

// Throws std::runtime_error for an unknown plugin (message lists the plugins found) or
// estimator::ParameterError for a bad parameter.
CompareResult run_compare(const CompareConfig& config, const ProgressCallback& progress = {});

// A fixed-width table: one row per case and plugin, errors beside the bound and their ratios.
void write_report(std::ostream& out, const CompareResult& result);
// The same numbers as CSV (header line first).
void write_csv(std::ostream& out, const CompareResult& result);
// The mean errors per azimuth of every case and plugin, with the bounds (one row each): what
// plumb-plot compare-grid draws, error versus azimuth per inclination like the source paper's figure.
void write_azimuth_points_csv(std::ostream& out, const CompareResult& result);

}  // namespace plumb::compare
