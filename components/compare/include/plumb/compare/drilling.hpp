// `plumb compare --scenario drilling`: drilling runs from the simulator (sim/drilling.hpp) through
// a navigator plugin (strapdown), errors against the exact truth over the whole run, beside the
// figures the source reports for its gyro inclinometer (docs/methods.md section 4).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "plumb/sim/rig_depth.hpp"

namespace plumb::compare {

// The source's result over 15 minutes: attitude within 2 deg, north/east velocity within 2 m/s,
// down within 4 m/s.
inline constexpr double kSourceAttitudeDeg = 2.0;
inline constexpr double kSourceHorizontalVelocityMps = 2.0;
inline constexpr double kSourceDownVelocityMps = 4.0;

// How measured depth reaches the navigator: the families of input users feed it.
enum class DepthFamily {
  sensor,  // a depth sensor on every row, with depth_sd_m of white noise
  none,    // no depth at all
  rig,     // as rigs deliver it: reports once a second, noisy, rounded, late, held or left empty
  tally,   // no depth sensor: the pipe tally (each joint's measured length) turns each stop into a depth
};
// "yes", "no", "rig", "tally": the table's depth column and --depth's words.
const char* family_name(DepthFamily family);
// "depth", "no depth", "rig depth", "pipe tally": the plots' legend.
const char* family_label(DepthFamily family);

struct DrillingCompareConfig {
  std::string plugin = "strapdown";
  std::vector<std::string> grades{"tactical", "mems"};
  std::vector<double> rates_hz{100, 10};
  std::vector<DepthFamily> families{DepthFamily::sensor, DepthFamily::none};
  // The simulated depth sensor's noise (sensor and rig families), 1 sigma; the navigator is not told.
  double depth_sd_m = 0;
  // The rig family's reports; their noise is depth_sd_m.
  sim::RigDepthReports rig{1, 0, 0.01, 1, false};
  // The tally family: each joint measured to this (1 sigma), the navigator told the measured
  // lengths (pipe_tally_m) and this figure (pipe_tally_sd_m).
  double tally_sd_m = 0.02;
  // Gyro angle random walk and accelerometer noise of the simulated sensors, times this; the
  // navigator is told only the grade, as a user with a noisier sensor of that grade would.
  double noisier = 1;
  bool magnetometer = true;
  int seeds = 1;
  std::uint64_t base_seed = 1;
  std::vector<std::string> assignments;  // --param [PLUGIN.]KEY=VALUE
};

// One error sample over time (estimate minus truth at the estimate's time).
struct ErrorPoint {
  double t = 0;
  double inclination_deg = 0, azimuth_deg = 0, toolface_deg = 0;
  double north_m = 0, east_m = 0, down_m = 0;
};

struct DrillingRunResult {
  std::string grade;
  double rate_hz = 0;
  DepthFamily family = DepthFamily::sensor;
  std::uint64_t seed = 0;
  double drilled_m = 0;
  double max_attitude_deg = 0;          // largest of the inclination, azimuth, toolface errors
  double max_inclination_deg = 0, max_azimuth_deg = 0, max_toolface_deg = 0;
  double rms_inclination_deg = 0, rms_azimuth_deg = 0, rms_toolface_deg = 0;
  double end_position_m = 0;            // 3-D, at the last estimate
  double max_horizontal_velocity_mps = 0, max_down_velocity_mps = 0;
  double attitude_coverage = 0;         // RMS(error / reported sd) over I, A, T
  // The same per angle (the navigator filter's sigmas beside the windowed plugins').
  double inclination_coverage = 0, azimuth_coverage = 0, toolface_coverage = 0;
  double position_coverage = 0;         // RMS(error / reported sd) over N, E, D, every valid row
  double end_position_coverage = 0;     // the same at the last valid row only
  int attitude_ratios = 0;              // how many error/sd ratios attitude_coverage pools
  int estimates = 0, valid = 0;
  std::string first_invalid_reason;
  std::vector<ErrorPoint> errors;

  double end_position_percent() const { return drilled_m > 0 ? 100 * end_position_m / drilled_m : 0; }
};

// Throws plugin::Error / estimator::ParameterError before any run for a bad plugin or parameter,
// std::invalid_argument for a figure out of range (a negative noise, --noisier not above 0).
// progress(done, total) after each run (and once before the first).
std::vector<DrillingRunResult> run_drilling_compare(const DrillingCompareConfig& config,
                                                    const std::function<void(std::size_t, std::size_t)>& progress = {});

// The table, one row per run, after lines saying what each depth family in it fed the navigator.
void write_drilling_report(std::ostream& out, const std::vector<DrillingRunResult>& runs,
                           const DrillingCompareConfig& config = {});
// Errors over time, six panels (inclination, azimuth, toolface, north, east, down), one curve per run.
// Each run's errors over time, one row per point: what plumb-plot drilling draws.
void write_drilling_errors_csv(std::ostream& out, const std::vector<DrillingRunResult>& runs);

}  // namespace plumb::compare
