// plumb-calibrate: runs a calibration procedure (docs/calibration.md) offline from a recorded
// sensor file and a station list, or live over DDS guiding the operator; writes the coefficients
// file the bridge reads and a report, and publishes the coefficients on plumb/calibration.
#include <cstdio>

#include "live.hpp"
#include "offline.hpp"
#include "options.hpp"
#include "plumb/csv/files.hpp"

int main(int argc, char** argv) {
  using namespace plumb;
  calibrate_component::Options o;
  CLI::App app{"plumb-calibrate: accelerometer and magnetometer calibration (6pos, 24pos, lsq, mag); "
               "writes a coefficients file and a report, publishes the coefficients on plumb/calibration"};
  components::add_transport_options(app, o.transport);
  app.add_option("--procedure", o.procedure, "6pos | 24pos | lsq | mag")
      ->check(CLI::IsMember({"6pos", "24pos", "lsq", "mag"}))
      ->capture_default_str();
  app.add_option("--input", o.input, "offline: sensor CSV of raw outputs (docs/conventions.md columns)");
  app.add_option("--stations", o.stations,
                 "offline: station list CSV: name,start_s,end_s,orientation[,run][,ref_temp_c] (docs/calibration.md)");
  app.add_option("--output", o.output, "coefficients file to write (only on success)");
  app.add_option("--report", o.report, "report file to write (residuals, standard deviations, inclination error)");
  app.add_option("--base", o.base, "coefficients file giving what the procedure does not determine");
  app.add_option("--nominal", o.nominal, "coefficients file of the nominal (uncalibrated) conversion, for the report");
  app.add_option("--g", o.g, "local gravity, m/s^2")->capture_default_str();
  app.add_option("--total-field", o.total_field_ut, "mag: local total field, microtesla")->capture_default_str();
  app.add_option("--max-error-deg", o.max_error_deg,
                 "refuse coefficients whose predicted (3 sd) inclination error over all orientations and the "
                 "calibrated temperature range exceeds this")
      ->capture_default_str();
  app.add_option("--temperature-order", o.temperature_order,
                 "24pos: order 1..3 of each sensor's bias and scale drift in temperature; 0 chooses it from the data")
      ->capture_default_str();
  app.add_flag("--with-accelerometers", o.with_accelerometers,
               "mag: also calibrate the accelerometers (least squares) on the same positions");
  app.add_option("--tool-id", o.tool_id, "tool id written into the coefficients");
  app.add_option("--calibration-id", o.calibration_id, "calibration id (default: procedure and UTC time)");
  app.add_option("--accel-units", o.accel_units,
                 "units of the package's raw accelerometer outputs (m/s2, V, ...), written into the coefficients; "
                 "a bridge whose stream has other units refuses them (default with a simulated package: V)");
  app.add_option("--mag-units", o.mag_units,
                 "units of the package's raw magnetometer outputs (uT, counts, ...), as --accel-units "
                 "(default with a simulated package: counts)");
  app.add_flag("--publish", o.publish, "offline: also publish the coefficients on plumb/calibration");
  app.add_option("--linger", o.linger_s, "seconds to keep publishing for late joiners")->capture_default_str();
  app.add_flag("--live", o.live, "live over DDS: subscribe plumb/sensor/raw and guide the operator");
  app.add_option("--positions", o.positions, "live lsq/mag: number of positions")->capture_default_str();
  app.add_option("--station-seconds", o.station_s, "live: seconds recorded once the tool is settled")->capture_default_str();
  app.add_option("--timeout", o.timeout_s, "live: give up after this many seconds")->capture_default_str();
  app.add_option("--run", o.run, "live 24pos: temperature run name");
  app.add_flag("--simulate-turntable", o.simulate_turntable,
               "live: a simulated turntable and operator publish on plumb/sensor/raw");
  app.add_option("--sim-speed", o.sim_speed, "simulated turntable: times faster than real time")->capture_default_str();
  app.add_option("--sim-seed", o.sim_seed, "simulated sensor package seed")->capture_default_str();
  app.add_option("--sim-misplace", o.sim_misplace,
                 "live simulated turntable: the operator puts position N (1-based) wrong once, z axis down")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--sim-truth", o.sim_truth,
                 "simulations: coefficients file with the simulated package's true coefficients (default: typical "
                 "errors from --sim-seed)");
  app.add_option("--write-simulation", o.write_simulation,
                 "write a simulated recording for --procedure: PREFIXsensor.csv, PREFIXstations.csv, PREFIXtruth.txt, "
                 "PREFIXnominal.txt, then exit");
  app.name("plumb-calibrate");
  if (const int status = components::parse_command_line(app, argc, argv); status >= 0) return status;
  if (o.positions < 1 || o.station_s <= 0 || o.linger_s < 0 || o.timeout_s <= 0 || o.sim_speed <= 0 || o.g <= 0 ||
      !(o.max_error_deg > 0)) {
    components::print_error("plumb-calibrate",
                            "--positions, --station-seconds, --timeout, --sim-speed, --g, --max-error-deg must be positive");
    return components::kUsageError;
  }
  if (o.temperature_order < 0 || o.temperature_order > 3) {
    components::print_error("plumb-calibrate", "--temperature-order must be 0 (from the data), 1, 2 or 3");
    return components::kUsageError;
  }
  try {
    components::install_stop_handler();
    if (!o.write_simulation.empty()) return calibrate_component::write_simulation(o);
    if (o.live) return calibrate_component::run_live(o);
    return calibrate_component::run_offline(o);
  } catch (const std::exception& e) {
    return components::exit_on_error("plumb-calibrate", e);
  }
}
