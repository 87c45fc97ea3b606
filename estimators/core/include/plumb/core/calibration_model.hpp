// How calibration coefficients turn raw sensor outputs into physical units (docs/calibration.md).
// The calibration procedures produce a CalibrationModel; the bridge applies it to every sample.
//
// For each triad, with T the corrected temperature and T0 the reference temperature:
//   v = u - (bias + bias_temp * (T - T0))                 raw output with bias removed
//   w = diag(1 + scale_temp * (T - T0)) * S * v          linear part
//   a solves a + k2 .* a.^2 = w  (per axis)               second-order (non-linear) term
// The thermometer reading t is corrected first: T = c0 + c1 t + c2 t^2 + c3 t^3.
#pragma once

#include <array>
#include <iosfwd>
#include <string>

#include <Eigen/Core>

#include "plumb/core/sample.hpp"

namespace plumb {

struct TriadModel {
  Eigen::Vector3d bias = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sensitivity = Eigen::Matrix3d::Identity();
  Eigen::Vector3d second_order = Eigen::Vector3d::Zero();
  Eigen::Vector3d bias_temp = Eigen::Vector3d::Zero();
  Eigen::Vector3d scale_temp = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& raw, double dT) const;
  bool is_identity() const;
};

struct CalibrationModel {
  std::string tool_id;
  std::string calibration_id;
  double stamp_s = 0;            // when the procedure ended (unix time)
  double reference_temp_c = 25;
  double temp_min_c = -40;       // calibrated range
  double temp_max_c = 200;
  std::array<double, 4> thermometer{0, 1, 0, 0};
  TriadModel accelerometer;
  TriadModel magnetometer;

  double corrected_temperature(double raw_temp_c) const;
  // Calibrates f and b (and temp_c) in place; sets flags::kCalibrated, and
  // flags::kTemperatureOutOfRange when T is outside [temp_min_c, temp_max_c].
  void apply(Sample& s) const;
};

// The coefficients text file (docs/calibration.md): "key value..." lines, '#' comments.
// Throws std::runtime_error naming the line on a bad file.
CalibrationModel read_calibration_file(const std::string& path);
CalibrationModel parse_calibration(std::istream& in, const std::string& source_name);
void write_calibration(std::ostream& out, const CalibrationModel& model);

}  // namespace plumb
