// The command-line options that describe the simulated scenario, and their translation into a
// sim::Scenario (the rotating platform), a sim::DrillingScenario (--scenario drilling...) or a
// sim::WalkScenario (--scenario walk).
// Options given explicitly override the preset.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "plumb/sim/drilling.hpp"
#include "plumb/sim/platform.hpp"
#include "plumb/sim/walk.hpp"

namespace plumb::sim_component {

struct ScenarioOptions {
  std::string scenario = "platform";  // platform, drilling, drilling-survey, walk
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
  double vibration_rms = 0, vibration_hz = 15, vibration_band = 0, shock_rate = 0, shock_peak = 0;
  std::string temp;
  unsigned long long seed = 1;
  std::string tool_id = "sim";
  bool no_gyro = false;
  // Drilling runs and walks.
  std::string grade = "tactical";     // walks: mems unless given
  double gyro_range = 0;
  bool no_mag = false, no_depth = false;
  double depth_noise = 0, depth_step = 0;
  std::vector<std::string> mag_disturbances;  // STOP:DELTA_UT:DELTA_DIP_DEG
  std::string circulation_temp;               // MUD_C:FORMATION_C (drilling: the tool's temperature)
  // Walks only.
  double walk_length = 25, walk_climb = 0;
};

// Registers the scenario options on `app`, storing into `options`.
void add_scenario_options(CLI::App& app, ScenarioOptions& options);

// The scenario the parsed options describe. Throws std::invalid_argument with a one-line message
// naming the option at fault.
sim::Scenario make_scenario(const CLI::App& app, const ScenarioOptions& options);

// True for --scenario drilling and drilling-survey.
bool is_drilling(const ScenarioOptions& options);

// The drilling run the parsed options describe: the named run (DrillingScenario::reference or
// survey_stop_and_go) with the options given explicitly applied. Platform-only options are refused
// by name, as are bad values.
sim::DrillingScenario make_drilling_scenario(const CLI::App& app, const ScenarioOptions& options);

// True for --scenario walk.
bool is_walk(const ScenarioOptions& options);

// The walk the parsed options describe: WalkScenario::loop_25m, loop_60m or loop(--walk-length,
// --walk-climb), with the options given explicitly applied. Options of the platform and of drilling
// runs that a walk would ignore are refused by name, as are bad values.
sim::WalkScenario make_walk_scenario(const CLI::App& app, const ScenarioOptions& options);

}  // namespace plumb::sim_component
