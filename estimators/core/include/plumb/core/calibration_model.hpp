// How calibration coefficients turn raw sensor outputs into physical units (docs/calibration.md).
// The calibration procedures produce a CalibrationModel; the bridge applies it to every sample.
//
// For each triad, with T the corrected temperature, T0 the reference temperature and d = T - T0:
//   s = 1 + s1 d + s2 d^2 + s3 d^3                        each sensor's own scale drift (version 2)
//   v = u ./ s - (bias + bias_temp d + bias_temp2 d^2 + bias_temp3 d^3)   on the sensor's output
//   w = diag(1 + scale_temp * d) * S * v                 linear part (scale_temp: version 1, tool axes)
//   a solves a + k2 .* a.^2 = w  (per axis)               second-order (non-linear) term
// The version-2 terms (bias_temp2, bias_temp3, sensor_scale_temp1..3) put the temperature drift
// where a real sensor has it, on its own output before the matrix that maps sensor axes to tool
// axes (docs/methods.md section 3: output_i = k_i(T) (a_i + b_i(T) + ...)). With them all zero the model is
// version 1 exactly, and a version-1 file means what it always meant.
// The thermometer reading t is corrected first: T = c0 + c1 t + c2 t^2 + c3 t^3.
#pragma once

#include <array>
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
  // Version 2: higher orders of the bias drift (raw units per degC^2, degC^3) and each sensor's
  // scale drift on its own output (per degC^p).
  Eigen::Vector3d bias_temp2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d bias_temp3 = Eigen::Vector3d::Zero();
  Eigen::Vector3d sensor_scale_temp1 = Eigen::Vector3d::Zero();
  Eigen::Vector3d sensor_scale_temp2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d sensor_scale_temp3 = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& raw, double dT) const;
  // The exact inverse of apply: the raw output this model turns into `physical` at dT.
  Eigen::Vector3d raw_for(const Eigen::Vector3d& physical, double dT) const;
  // Raw-unit bias at dT (all orders) and each sensor's relative scale 1 + s1 dT + s2 dT^2 + s3 dT^3.
  Eigen::Vector3d bias_at(double dT) const;
  Eigen::Vector3d sensor_scale_at(double dT) const;
  bool is_identity() const;
  bool has_version2_terms() const;
};

struct CalibrationModel {
  std::string tool_id;
  std::string calibration_id;
  // Units of the raw outputs the coefficients were made for (what the package sends in the f and
  // b channels: "m/s2", "V", "counts", ...). Empty: not stated (a file without the line, as every
  // version-1 file before the units lines): the bridge can then only catch a mismatch by the |G|
  // check of the calibrated stream.
  std::string accel_units;
  std::string mag_units;
  double stamp_s = 0;            // when the procedure ended (unix time)
  double reference_temp_c = 25;
  double temp_min_c = -40;       // calibrated range
  double temp_max_c = 200;
  std::array<double, 4> thermometer{0, 1, 0, 0};
  TriadModel accelerometer;
  TriadModel magnetometer;

  double corrected_temperature(double raw_temp_c) const;
  // 2 when a triad has version-2 temperature terms, else 1 (the version the file is written in).
  int format_version() const;
  // Calibrates f and b (and temp_c) in place; sets flags::kCalibrated, and
  // flags::kTemperatureOutOfRange when T is outside [temp_min_c, temp_max_c].
  void apply(Sample& s) const;
};

}  // namespace plumb
