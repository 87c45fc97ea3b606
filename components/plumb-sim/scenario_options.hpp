// The command-line options that describe the simulated scenario, and their translation into a
// sim::Scenario. Options given explicitly override the preset.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "plumb/sim/platform.hpp"

namespace plumb::sim_component {

struct ScenarioOptions {
  std::string preset = "default";
  double inclination_deg = 1, azimuth_deg = 0, toolface_deg = 0;
  double rpm = 60;
  std::string profile;
  double g = 9.80665, field = 48.4, dip = 45.5, latitude = 45;
  double rate_hz = 100, duration_s = 10;
  long long count = 0;
  double snr_accel = 20, snr_mag = 20;
  double sigma_accel = 0, sigma_mag = 0, sigma_gyro = 0;
  std::string accel_bias, accel_scale, accel_bias_temp, mag_bias, mag_scale, mag_bias_temp, gyro_bias, gyro_scale;
  double vibration_rms = 0, vibration_hz = 15, shock_rate = 0, shock_peak = 0;
  std::string temp;
  unsigned long long seed = 1;
  std::string tool_id = "sim";
  bool no_gyro = false;
};

// Registers the scenario options on `app`, storing into `options`.
void add_scenario_options(CLI::App& app, ScenarioOptions& options);

// The scenario the parsed options describe. Throws std::invalid_argument with a one-line message
// naming the option at fault.
sim::Scenario make_scenario(const CLI::App& app, const ScenarioOptions& options);

}  // namespace plumb::sim_component
