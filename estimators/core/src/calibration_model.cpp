#include "plumb/core/calibration_model.hpp"

#include <cmath>

#include <Eigen/LU>

namespace plumb {

namespace {

// The root of k2 a^2 + a - w = 0 that tends to w as k2 -> 0, written so that it does not lose
// precision when k2 w is tiny (the usual case: k2 ~ 1e-5 per m/s^2).
double solve_second_order(double w, double k2) {
  if (k2 == 0.0) return w;
  const double disc = 1.0 + 4.0 * k2 * w;
  // Beyond the turning point of the quadratic there is no real inverse: the reading is outside
  // what the model describes, so return the linear part rather than NaN.
  if (!(disc > 0.0)) return w;
  return 2.0 * w / (1.0 + std::sqrt(disc));
}

}  // namespace

Eigen::Vector3d TriadModel::bias_at(double dT) const {
  return bias + dT * (bias_temp + dT * (bias_temp2 + dT * bias_temp3));
}

Eigen::Vector3d TriadModel::sensor_scale_at(double dT) const {
  return Eigen::Vector3d::Ones() + dT * (sensor_scale_temp1 + dT * (sensor_scale_temp2 + dT * sensor_scale_temp3));
}

Eigen::Vector3d TriadModel::apply(const Eigen::Vector3d& raw, double dT) const {
  // The sensor's own scale drift first: it multiplies everything that sensor outputs, bias included.
  const Eigen::Vector3d v = raw.cwiseQuotient(sensor_scale_at(dT)) - bias_at(dT);
  const Eigen::Vector3d scale = Eigen::Vector3d::Ones() + scale_temp * dT;
  const Eigen::Vector3d w = scale.asDiagonal() * (sensitivity * v);
  Eigen::Vector3d a;
  for (int i = 0; i < 3; ++i) a[i] = solve_second_order(w[i], second_order[i]);
  return a;
}

Eigen::Vector3d TriadModel::raw_for(const Eigen::Vector3d& x, double dT) const {
  const Eigen::Vector3d w = x + second_order.cwiseProduct(x.cwiseAbs2());
  const Eigen::Vector3d scale = Eigen::Vector3d::Ones() + scale_temp * dT;
  const Eigen::Vector3d v = sensitivity.lu().solve(w.cwiseQuotient(scale));
  return (v + bias_at(dT)).cwiseProduct(sensor_scale_at(dT));
}

bool TriadModel::is_identity() const {
  return bias.isZero(0) && sensitivity == Eigen::Matrix3d::Identity() && second_order.isZero(0) &&
         bias_temp.isZero(0) && scale_temp.isZero(0) && !has_version2_terms();
}

bool TriadModel::has_version2_terms() const {
  return !(bias_temp2.isZero(0) && bias_temp3.isZero(0) && sensor_scale_temp1.isZero(0) &&
           sensor_scale_temp2.isZero(0) && sensor_scale_temp3.isZero(0));
}

int CalibrationModel::format_version() const {
  return accelerometer.has_version2_terms() || magnetometer.has_version2_terms() ? 2 : 1;
}

double CalibrationModel::corrected_temperature(double t) const {
  return thermometer[0] + t * (thermometer[1] + t * (thermometer[2] + t * thermometer[3]));
}

void CalibrationModel::apply(Sample& s) const {
  // Without a thermometer reading the temperature terms cannot be applied: calibrate at the
  // reference temperature and leave temp_c alone.
  double dT = 0.0;
  if (s.flags & flags::kHasTemperature) {
    const double T = corrected_temperature(s.temp_c);
    s.temp_c = T;
    dT = T - reference_temp_c;
    if (!(T >= temp_min_c && T <= temp_max_c)) s.flags |= flags::kTemperatureOutOfRange;
  }
  s.f = accelerometer.apply(s.f, dT);
  s.b = magnetometer.apply(s.b, dT);
  s.flags |= flags::kCalibrated;
}

}  // namespace plumb
