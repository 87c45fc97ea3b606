// A drilling run for the strapdown navigator (docs/methods.md section 4, docs/conventions.md
// "Navigation"): the tool advances along its own z axis while building and turning, sliding
// (toolface fixed) or rotary (toolface turning), and stands perfectly still for pipe connections.
// Gyros, accelerometers, magnetometers and the rig's measured depth are exact functions of one
// smooth trajectory, so an error-free IMU integrated from the true initial state returns the truth.
//
// Kinematics, all closed form (no integration inside the simulator):
//   measured depth s(t): raised-cosine speed ramps of DrillingPlan::ramp_s at each start and stop,
//     so speed and acceleration are continuous;
//   I(s), A(s): linear in s within a segment (build and turn rates), T: held (sliding) or
//     T0 + (omega / rop) (s - s0) (rotary: the rotation speed ramps with the drilling speed);
//   position: the exact integral of (sinI cosA, sinI sinA, cosI) ds (round-off only).
// Sensors: w_ib = w_nb + C_n^b w_ie, f = C_n^b (dv/dt + 2 w_ie x v - g_n), B = C_n^b B_n. Samples
// are instantaneous values at their time stamp t = k / rate (not averages over the interval).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/core/sample.hpp"
#include "plumb/sim/imu_model.hpp"
#include "plumb/sim/platform.hpp"
#include "plumb/sim/tool_temperature.hpp"

namespace plumb::sim {

enum class SegmentKind { Drill, Stop };
enum class SteeringMode { Sliding, Rotary };

// One step of the plan. Drill: length_m, or duration_s (including both speed ramps; the length is
// then rop * (duration - ramp)). Stop: duration_s of perfect stillness (a pipe connection).
struct DrillSegment {
  SegmentKind kind = SegmentKind::Drill;
  double length_m = 0;
  double duration_s = 0;
  double rop_mps = 0.05;             // rate of penetration while cruising
  double build_deg_per_30m = 0;      // dI/ds
  double turn_deg_per_30m = 0;       // dA/ds
  SteeringMode mode = SteeringMode::Sliding;
  double rpm = 0;                    // Rotary: toolface speed while cruising (positive: T increases)

  static DrillSegment drill(double length_m, double rop_mps, double build_deg_per_30m = 0,
                            double turn_deg_per_30m = 0);
  static DrillSegment rotary(double length_m, double rop_mps, double rpm, double build_deg_per_30m = 0,
                             double turn_deg_per_30m = 0);
  static DrillSegment stop(double duration_s);
};

struct DrillingPlan {
  double inclination_deg = 85;   // at the start (collar of this run), within [0, 180]
  double azimuth_deg = 30;       // magnetic
  double toolface_deg = 0;       // gravity toolface at the start; sliding segments keep the current one
  double alignment_s = 60;       // still period before the first segment
  double ramp_s = 5;             // raised-cosine speed change at each start and stop of drilling
  // Stick-slip of rotary segments: the spin rate oscillates by +-stick_slip_rpm (scaled by the
  // drive, so it fades in and out with the speed ramps) with this period; the toolface at each
  // segment's end is unchanged. 0: a steady spin (the default).
  double stick_slip_rpm = 0;
  double stick_slip_period_s = 4;
  std::vector<DrillSegment> segments;
};

// A magnetic disturbance during one stop: |B| and dip shifted while the tool stands.
struct MagneticDisturbance {
  std::size_t stop_index = 0;    // 0 = first Stop segment of the plan (the alignment is not a stop)
  double delta_total_uT = 0;
  double delta_dip_deg = 0;
};

struct MagnetometerModel {
  bool present = true;           // false: Sample::b stays zero (no magnetometer on the tool)
  double sigma_uT = 0;           // white noise per axis per sample
  // The drill string's magnetization: a bias along the tool axis, the same at every sample.
  double axial_bias_sd_uT = 0;   // the spread it is drawn from (per seed) when not given
  std::optional<double> axial_bias_uT;
  std::vector<MagneticDisturbance> disturbances;
};

struct DepthModel {
  bool present = true;           // Sample::depth_m with flags::kHasDepth
  double sigma_m = 0;            // white noise per sample
  double quantum_m = 0;          // rounding step of the rig's reading (after the noise); 0: none
  // A floating rig's heave compensator leaves a residual on the measured depth only (the tool does
  // not move with it): a swell of this amplitude and period, its phase drawn from the seed. 0: none.
  double heave_amplitude_m = 0;
  double heave_period_s = 10;
};

struct DrillingScenario {
  std::string tool_id = "drill";
  DrillingPlan plan;
  ImuGrade grade = ImuGrade::perfect();
  std::optional<Eigen::Vector3d> gyro_bias;    // rad/s; default: drawn from the grade and the seed
  std::optional<Eigen::Vector3d> accel_bias;   // m/s^2; default: drawn from the grade and the seed
  double sample_rate_hz = 100;
  double latitude_deg = 35;
  double g = 9.80665;            // m/s^2
  double total_b = 50;           // microtesla
  double dip_deg = 60;
  double earth_rate = 7.292115e-5;  // rad/s
  MagnetometerModel magnetometer;
  DepthModel depth;
  Vibration vibration;           // lateral, added to f while drilling only, scaled by the speed ramp
  // The tool heating at stops and cooling while mud circulates, and the biases following it
  // (tool_temperature.hpp). Off: no temperature on the samples, constant biases.
  ToolTemperature temperature;
  std::uint64_t seed = 1;

  // The navigator's accuracy case: 16 min = 60 s alignment, then four drilling segments of 165 s
  // (8 m each at 0.05 m/s: sliding with build, rotary at 30 rpm, sliding with build and turn,
  // rotary with turn) each followed by a 60 s pipe connection; I 85 -> ~89 deg, A 30 -> ~28 deg;
  // latitude 35 deg, B 50 uT, dip 60 deg, g 9.80665; magnetometer noise 0.1 uT; no vibration.
  static DrillingScenario reference(const ImuGrade& grade, double rate_hz = 100, std::uint64_t seed = 1);
  // Stop-and-go rotary drilling with short survey stops: I 45 deg, A 120 deg, 60 rpm, six 1.5 m
  // segments at 0.05 m/s, each followed by a 30 s survey stop; 60 s alignment.
  static DrillingScenario survey_stop_and_go(const ImuGrade& grade, double rate_hz = 100, std::uint64_t seed = 1);

  double duration_s() const;     // alignment + all segments
};

// The true state at one instant.
struct DrillingState {
  double t = 0;
  double depth_m = 0;            // measured depth s
  double speed_mps = 0;          // ds/dt
  double drive = 0;              // speed / cruise rop of the segment, 0..1 (0 when still)
  bool still = true;             // exactly zero velocity and constant attitude
  std::size_t phase = 0;         // index into DrillingTrajectory::phases()
  double inclination = 0, azimuth = 0, toolface = 0;  // rad; toolface unwrapped
  double toolface_rate = 0;      // rad/s
  Eigen::Matrix3d c_nb = Eigen::Matrix3d::Identity();
  Eigen::Vector3d w_nb = Eigen::Vector3d::Zero();      // rad/s, tool frame
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // NED from the collar, m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // NED, m/s
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // dv/dt, NED, m/s^2
};

// The plan compiled into phases of constant parameters, evaluated in closed form at any t.
class DrillingTrajectory {
 public:
  struct Phase {
    bool moving = false;
    double t0 = 0, t1 = 0;          // s
    double rop = 0, ramp = 0;       // m/s, s
    double build = 0, turn = 0;     // rad/m
    double spin = 0;                // toolface rad per metre drilled (rotary)
    double slip = 0, slip_w = 0;    // stick-slip: rate amplitude (rad/s) and angular frequency (rotary)
    double s0 = 0, inc0 = 0, azi0 = 0, tf0 = 0;  // at t0
    Eigen::Vector3d p0 = Eigen::Vector3d::Zero();
    std::optional<std::size_t> stop_index;        // Stop segments: their index among the stops
  };
  // Throws std::invalid_argument with a readable message for a bad plan.
  explicit DrillingTrajectory(const DrillingPlan& plan);
  double duration_s() const { return phases_.back().t1; }
  double drilled_length_m() const;
  std::size_t stop_count() const { return stops_; }
  const std::vector<Phase>& phases() const { return phases_; }
  // Past the end the tool stays where the plan left it.
  DrillingState at(double t) const;
  bool still_at(double t) const;

 private:
  std::size_t phase_at(double t) const;
  std::vector<Phase> phases_;
  std::size_t stops_ = 0;
};

// Produces the samples of a drilling run one at a time, deterministic for a seed.
class DrillingSimulator {
 public:
  // Throws std::invalid_argument with a readable message for bad parameters.
  explicit DrillingSimulator(const DrillingScenario& scenario);
  std::size_t sample_count() const;   // duration x rate, rounded
  bool done() const;
  // Next sample (gyros flagged kHasGyro, depth kHasDepth) and its truth (with position). Past
  // sample_count() the tool stays still at the end of the plan.
  Sample next(TruthSample* truth = nullptr);
  std::vector<Sample> run(std::vector<TruthSample>* truth = nullptr);
  // True while the tool stands perfectly still (alignment and stops): the truth for a detector.
  bool still_at(double t) const { return trajectory_.still_at(t); }
  double time_of(std::size_t index) const;
  const DrillingScenario& scenario() const { return scenario_; }
  double magnetometer_axial_bias_uT() const { return axial_bias_uT_; }
  const DrillingTrajectory& trajectory() const { return trajectory_; }
  const Eigen::Vector3d& gyro_bias() const { return imu_.gyro_bias(); }    // the biases in use (truth)
  const Eigen::Vector3d& accel_bias() const { return imu_.accel_bias(); }
  // With the tool's temperature simulated: the true temperature at t (degC; the start's without),
  // and the run's drawn coefficients (rad/s and m/s^2 per degC): bias(t) = bias() + k (T(t) - T(0)).
  double temperature_at(double t) const;
  const Eigen::Vector3d& gyro_bias_temp() const { return imu_.gyro_bias_temp(); }
  const Eigen::Vector3d& accel_bias_temp() const { return imu_.accel_bias_temp(); }
  std::size_t index() const { return index_; }

 private:
  Eigen::Vector3d vibration_at(double t, double drive);
  Eigen::Vector3d field_at(const DrillingState& state) const;

  DrillingScenario scenario_;
  double axial_bias_uT_ = 0;
  DrillingTrajectory trajectory_;
  ImuModel imu_;
  std::size_t index_ = 0;
  std::mt19937_64 rng_;        // sensor noise
  std::mt19937_64 vib_rng_;    // vibration: separate, so the noise does not depend on it
  std::mt19937_64 temp_rng_;   // the temperature sensor's noise: separate, for the same reason
  TemperatureHistory temperature_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  VibrationTones tones_;
  double shock_until_ = -1, shock_start_ = 0, shock_dir_ = 0, shock_drive_ = 0, next_shock_ = 0;
};

// Angular rate of the tool frame against n, in the tool frame, from the attitude and its rates:
// w_nb = T' e3 + R3(T) (I' e2) + R3(T) R2(I) (A' e3).
Eigen::Vector3d rate_nb(double inc, double tf, double inc_rate, double azi_rate, double tf_rate);

// One readable line: plan, attitude, grade, environment, rate, seed.
std::string describe(const DrillingScenario& scenario);

}  // namespace plumb::sim
