// Everything plumb-calibrate is told on its command line.
#pragma once

#include <string>

#include "plumb/components/cli.hpp"

namespace plumb::calibrate_component {

struct Options {
  std::string procedure = "6pos";   // 6pos | 24pos | lsq | mag
  // Offline
  std::string input;                // sensor CSV (raw units)
  std::string stations;             // station list CSV
  // Both
  std::string output;               // coefficients file
  std::string report;               // report file
  std::string base;                 // coefficients the procedure does not determine come from here
  std::string nominal;              // what "uncalibrated" means in the report
  double g = 9.80665;
  double total_field_ut = 48.4;
  double max_error_deg = 0.005;     // no coefficients whose predicted inclination error exceeds this
  int temperature_order = 0;        // 24pos: order of the sensors' drift in temperature (0: from the data)
  bool with_accelerometers = false; // mag: also calibrate the accelerometers (least squares)
  std::string tool_id;
  std::string calibration_id;
  std::string accel_units;          // units of the package's raw outputs, written into the coefficients
  std::string mag_units;
  bool publish = false;             // offline: also publish the coefficients
  double linger_s = 5;
  // Live
  bool live = false;
  int positions = 16;               // lsq / mag: how many positions to ask for
  double station_s = 10;            // how long to record once settled
  double timeout_s = 900;
  std::string run;                  // 24pos: the temperature run's name
  bool simulate_turntable = false;
  double sim_speed = 20;            // simulated turntable: times faster than real time
  std::uint64_t sim_seed = 1;
  int sim_misplace = 0;             // simulated operator: position (1-based) put wrong once; 0: none
  std::string sim_truth;            // coefficients file: the simulated package's true coefficients
  // Simulation export
  std::string write_simulation;     // prefix: writes <prefix>sensor.csv, <prefix>stations.csv, <prefix>truth.txt
  components::TransportOptions transport;
};

}  // namespace plumb::calibrate_component
