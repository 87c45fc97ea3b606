// The rotating single-axis stabilized platform and its sensors (docs/methods.md section 1,
// docs/conventions.md). The tool holds a fixed inclination and azimuth; the sensor platform turns
// about the tool z axis with a rotation profile, so the gravity toolface T(t) is the platform angle.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/core/sample.hpp"
#include "plumb/sim/vibration.hpp"

namespace plumb::sim {

enum class ProfileKind { Constant, Ramp, StopAndGo, StickSlip };

struct RotationProfile {
  ProfileKind kind = ProfileKind::Constant;
  double rpm = 0;            // Constant: speed. Ramp: start speed. StopAndGo / StickSlip: mean speed.
  double rpm_end = 0;        // Ramp: speed at ramp_s
  double ramp_s = 10;        // Ramp duration; constant afterwards
  double period_s = 4;       // StopAndGo: turn for period/2 then stop; StickSlip: speed swings 0..2*mean
  // Platform angle (gravity toolface, rad, unwrapped) and rate (rpm) at time t, from toolface0 (rad).
  double angle(double t, double toolface0) const;
  double rpm_at(double t) const;
};

// Per-triad sensor errors: measured = M * true + bias (+ drift with temperature).
struct TriadErrors {
  Eigen::Vector3d bias = Eigen::Vector3d::Zero();
  Eigen::Vector3d scale = Eigen::Vector3d::Zero();         // relative, e.g. 0.001
  Eigen::Matrix3d misalignment = Eigen::Matrix3d::Zero();  // small off-diagonal terms, rad
  Eigen::Vector3d bias_temp = Eigen::Vector3d::Zero();     // bias change per degC from 25 degC
};

struct Noise {
  // Either sigma given directly or an SNR in dB (docs/conventions.md "Noise and signal-to-noise ratio").
  std::optional<double> sigma_accel;   // m/s^2
  std::optional<double> sigma_mag;     // microtesla
  std::optional<double> snr_accel_db;
  std::optional<double> snr_mag_db;
  double sigma_gyro = 0;               // rad/s
};

struct Scenario {
  std::string tool_id = "sim";
  double g = 9.80665;          // m/s^2
  double total_b = 48.4;       // microtesla
  double dip_deg = 45.5;
  double inclination_deg = 1;
  double azimuth_deg = 0;      // magnetic
  double toolface0_deg = 0;    // platform angle at t = 0
  RotationProfile rotation;
  double sample_rate_hz = 100;
  double duration_s = 10;
  Noise noise;
  TriadErrors accel_errors;
  TriadErrors mag_errors;
  TriadErrors gyro_errors;
  Vibration vibration;
  double temp_start_c = 25;    // temperature drifts linearly from start to end over the run
  double temp_end_c = 25;
  double earth_rate = 7.292115e-5;  // rad/s; gyros see it plus the platform rate
  double latitude_deg = 45;
  std::uint64_t seed = 1;
  bool with_gyro = true;

  // The paper's case: g = 10, B = 48.4 uT, dip 45.5 deg, 100 Hz, 10 s, SNR_m = 20 dB.
  static Scenario reference(double inclination_deg, double azimuth_deg, double rpm, double snr_accel_db,
                            std::uint64_t seed = 1);
  // Noise standard deviations this scenario implies (SNR converted where given).
  double sigma_accel() const;
  double sigma_mag() const;
  // Temperature at time t: linear from temp_start_c to temp_end_c over the duration, then held.
  double temperature_at(double t) const;
};

// Produces the samples of a scenario one at a time, deterministic for a given seed.
class PlatformSimulator {
 public:
  explicit PlatformSimulator(const Scenario& scenario);
  std::size_t sample_count() const;
  bool done() const;
  // Next sample, and the truth at that instant. It keeps going past sample_count() (continuous
  // platform angle, temperature held at its end value): a component may loop without a jump.
  Sample next(TruthSample* truth = nullptr);
  // All samples (convenience for tests).
  std::vector<Sample> run(std::vector<TruthSample>* truth = nullptr);
  const Scenario& scenario() const { return scenario_; }
  std::size_t index() const { return index_; }  // samples produced so far

 private:
  Eigen::Vector3d vibration_at(double t);
  Scenario scenario_;
  std::size_t index_ = 0;
  std::mt19937_64 rng_;        // sensor noise
  std::mt19937_64 vib_rng_;    // vibration and shocks: separate, so the noise does not depend on them
  std::normal_distribution<double> normal_{0.0, 1.0};
  double sigma_accel_ = 0, sigma_mag_ = 0;
  VibrationTones tones_;
  double shock_until_ = -1, shock_start_ = 0, shock_dir_ = 0, next_shock_ = 0;
};

// Parses a profile description: "60" (constant), "ramp:0:120:5", "stopgo:60:4", "stickslip:60:2".
// Throws std::invalid_argument with a message saying what is accepted.
RotationProfile parse_profile(const std::string& text);

// One readable line for logs: "stick-slip, mean 60 rpm, period 2 s".
std::string describe(const RotationProfile& profile);
// One readable line: attitude, rotation, environment, rate and duration, noise, errors, seed.
std::string describe(const Scenario& scenario);

}  // namespace plumb::sim
