// The IMU of a simulated run, shared by the drilling and walking simulators: its error levels
// (ImuGrade, by name or by value) and one run's sensors drawn from them (ImuModel): biases, white
// noise, gyro clipping and the earth's rate. Sensors as in docs/conventions.md "Navigation":
// w_ib = w_nb + C_n^b w_ie, f = C_n^b (dv/dt + 2 w_ie x v - g_n).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "plumb/core/sample.hpp"

namespace plumb::sim {

// IMU error levels. Biases are constant over a run, drawn per axis as N(0, bias^2) from the seed
// unless given explicitly (DrillingScenario::gyro_bias / accel_bias); white noise per sample has
// sigma = density / sqrt(dt) (ARW for gyros, VRW for accelerometers). Named grades:
//   grade       gyro bias  gyro ARW     accel bias  accel VRW       gyro range
//               deg/h      deg/sqrt(h)  mg          m/s/sqrt(h)     deg/s
//   navigation  0.01       0.002        0.025       0.005           500
//   tactical    1          0.05         0.3         0.03            1000
//   mems        10         0.3          2           0.06            2000
//   perfect     0          0            0           0               unlimited
struct ImuGrade {
  std::string name = "perfect";
  double gyro_bias_deg_h = 0;      // 1-sigma per axis
  double gyro_arw_deg_rt_h = 0;    // angle random walk
  double accel_bias_mg = 0;        // 1-sigma per axis; 1 mg = 9.80665e-3 m/s^2
  double accel_vrw_mps_rt_h = 0;   // velocity random walk
  double gyro_range_deg_s = 0;     // samples beyond +-range are clipped and flagged; 0: unlimited
  // Accelerometer range: samples beyond +-range on an axis sit at the range, flagged saturated
  // (a shock of tens of g on a +-16 g MEMS part). 0 (every named grade): unlimited.
  double accel_range_g = 0;
  // Bias temperature coefficients as a datasheet states them (typical, per axis): what the biases
  // change by per degC when the run's tool temperature is simulated (ToolTemperature). A run's
  // actual coefficients are drawn around them (ImuModel). Named grades:
  //   navigation 0.002 deg/h/degC, 0.002 mg/degC; tactical 0.05, 0.01; mems 0.2, 0.05; perfect 0.
  double gyro_bias_temp_dph_per_c = 0;
  double accel_bias_temp_mg_per_c = 0;

  static ImuGrade navigation();
  static ImuGrade tactical();
  static ImuGrade mems();
  static ImuGrade perfect();
  // "navigation", "tactical", "mems" or "perfect"; throws std::invalid_argument otherwise.
  static ImuGrade named(const std::string& name);

  // The same in SI units for a sample period dt (s).
  double gyro_bias_sigma() const;               // rad/s
  double accel_bias_sigma() const;              // m/s^2
  double gyro_noise_sigma(double dt) const;     // rad/s per sample
  double accel_noise_sigma(double dt) const;    // m/s^2 per sample
  double gyro_range() const;                    // rad/s; infinity when unlimited
  double accel_range() const;                   // m/s^2; infinity when unlimited
  double gyro_bias_temp() const;                // rad/s per degC
  double accel_bias_temp() const;               // m/s^2 per degC
};

// One run's IMU, shared by the drilling and walking simulators: the grade's biases drawn from the
// seed (or given), white noise per sample, gyro clipping, and the earth rate at the latitude. The
// biases' temperature coefficients are drawn per axis as stated x (1 + 0.25 N(0, 1)): a datasheet
// gives a typical value, and parts spread about it by some 20-30 %.
class ImuModel {
 public:
  ImuModel(const ImuGrade& grade, double rate_hz, std::uint64_t seed, const std::optional<Eigen::Vector3d>& gyro_bias,
           const std::optional<Eigen::Vector3d>& accel_bias, double earth_rate, double latitude_deg);
  // Gyros and accelerometers (flags kHasGyro, kGyroSaturated, kAccelSaturated) from the true motion: w_nb and C_n^b,
  // dv/dt and v in NED, g, a specific force added on top (vibration), and unit normal draws n_w and
  // n_a from the caller's noise stream; the biases shifted by their coefficients times delta_temp_c
  // (the tool's temperature less the run's start).
  void measure(const Eigen::Vector3d& w_nb, const Eigen::Matrix3d& c_nb, const Eigen::Vector3d& acceleration,
               const Eigen::Vector3d& velocity, double g, const Eigen::Vector3d& extra_f, const Eigen::Vector3d& n_w,
               const Eigen::Vector3d& n_a, Sample& out, double delta_temp_c = 0) const;
  const Eigen::Vector3d& gyro_bias() const { return gyro_bias_; }
  const Eigen::Vector3d& accel_bias() const { return accel_bias_; }
  // The run's drawn temperature coefficients (rad/s and m/s^2 per degC, per axis): the truth.
  const Eigen::Vector3d& gyro_bias_temp() const { return gyro_temp_; }
  const Eigen::Vector3d& accel_bias_temp() const { return accel_temp_; }

 private:
  Eigen::Vector3d gyro_bias_, accel_bias_, earth_rate_ned_;
  Eigen::Vector3d gyro_temp_ = Eigen::Vector3d::Zero(), accel_temp_ = Eigen::Vector3d::Zero();
  double sigma_gyro_ = 0, sigma_accel_ = 0, gyro_range_ = 0, accel_range_ = 0;
};

// One readable line: the grade's name and its error levels.
std::string describe(const ImuGrade& grade);

}  // namespace plumb::sim
