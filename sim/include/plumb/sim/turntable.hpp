// A calibration turntable in a temperature chamber (docs/methods.md sections 2 and 3): a sensor
// package with known true coefficients placed at a list of stations, producing raw outputs
// (volts, or pulse counts per unit time for quartz accelerometers; magnetometer counts; a raw,
// non-linear thermometer), with an exponential settling transient after every move and white noise.
//
// The package's truth is a plumb::CalibrationModel: the simulator produces raw outputs u such that
// truth.apply(u) gives back the true specific force and field exactly (before noise). A procedure
// that works recovers the truth.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/core/calibration_model.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::sim {

enum class AccelOutput { Voltage, PulseRate };

struct SensorPackage {
  CalibrationModel truth;     // raw -> physical, exactly
  CalibrationModel nominal;   // the datasheet conversion: what "uncalibrated" means
  AccelOutput accel_output = AccelOutput::Voltage;
  double accel_noise = 1e-3;       // m/s^2 per sample, white (in physical units; scaled to raw)
  double mag_noise = 0.02;         // microtesla per sample
  double thermometer_noise = 0.05; // degC per sample
  double settle_tau_s = 1.0;       // exponential settling after each move

  // Raw outputs for the true physical quantities at true temperature T (no noise).
  Eigen::Vector3d raw_accel(const Eigen::Vector3d& f, double T) const;
  Eigen::Vector3d raw_mag(const Eigen::Vector3d& b, double T) const;
  double raw_temperature(double T) const;

  // A package with errors of realistic size drawn from `seed`: biases, scale factors, misalignment,
  // second-order terms, temperature coefficients, and a thermometer that is non-linear above
  // about 175 degC. Voltage: 0.25 V per m/s^2; PulseRate: 1000 pulses/s per m/s^2.
  static SensorPackage typical(AccelOutput output, std::uint64_t seed, bool temperature_effects = true);
};

// One station: where the tool is (an attitude per docs/conventions.md), at what temperature, for how long.
struct StationPlan {
  std::string name;
  std::string orientation = "any";  // the label the station list will carry (+x, -y@90, any)
  std::string run;                  // temperature run
  double inclination_deg = 0;
  double azimuth_deg = 0;           // rotation about the vertical (the turntable angle)
  double toolface_deg = 0;
  double temperature_c = 25;
  double duration_s = 20;
  double settle_tau_s = -1;         // < 0: the package's
};

struct Rig {
  double g = 9.80665;
  double total_b = 48.4;            // microtesla
  double dip_deg = 45.5;
  double sample_rate_hz = 50;
  double move_s = 5;                // time between stations (no samples: the tool is being moved)
  double table_tilt_x_deg = 0.0;    // the table top is not level: rotation about north, then east
  double table_tilt_y_deg = 0.0;
  int reference_thermometers = 3;
  double reference_noise_c = 0.02;  // per reference reading (station average)
  std::uint64_t seed = 1;
};

// What was recorded at one station, with the truth.
struct RecordedStation {
  StationPlan plan;
  double start_s = 0, end_s = 0;
  std::vector<double> reference_temps_c;
  Eigen::Vector3d true_f = Eigen::Vector3d::Zero();   // specific force, tool frame
  Eigen::Vector3d true_b = Eigen::Vector3d::Zero();   // field, tool frame
};

struct Recording {
  std::vector<Sample> samples;        // raw, time-ordered, flags kHasTemperature
  std::vector<RecordedStation> stations;
};

// Attitude (deg) that puts `axis` (0..2) up (sign +1) or down (-1): f = sign g e_axis.
void axis_up_attitude(int axis, int sign, double& inclination_deg, double& toolface_deg);

// Station plans for each procedure.
std::vector<StationPlan> six_position_plan(double duration_s = 20, double temperature_c = 25);
std::vector<StationPlan> twenty_four_position_plan(const std::vector<double>& temperatures_c, double duration_s = 20);
// n static positions spread over all directions (unknown orientations), e.g. by hand.
std::vector<StationPlan> random_static_plan(int n, std::uint64_t seed, double duration_s = 20, double temperature_c = 25);

// Specific force and field in the tool frame for a plan on a rig (uses plumb::c_nb).
void true_vectors(const Rig& rig, const StationPlan& plan, Eigen::Vector3d& f, Eigen::Vector3d& b);

// Runs the stations in order. Deterministic for rig.seed.
Recording record(const SensorPackage& package, const Rig& rig, const std::vector<StationPlan>& plans);

// The same physics one sample at a time, for a live turntable that moves when told (the simulated
// operator of `plumb-calibrate --simulate-turntable`).
class TurntableStream {
 public:
  TurntableStream(const SensorPackage& package, const Rig& rig);
  // Puts the tool at a station from now on (settling transient from the current outputs).
  void move_to(const StationPlan& plan);
  Sample next();
  double time() const { return t_; }

 private:
  SensorPackage package_;
  Rig rig_;
  std::uint64_t seq_ = 0;
  double t_ = 0, moved_at_ = 0, tau_ = 1, temperature_ = 25;
  bool placed_ = false;
  Eigen::Vector3d from_a_ = Eigen::Vector3d::Zero(), from_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d target_a_ = Eigen::Vector3d::Zero(), target_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d now_a_ = Eigen::Vector3d::Zero(), now_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d phase_ = Eigen::Vector3d::Zero();
  std::uint64_t noise_state_;
};

}  // namespace plumb::sim
