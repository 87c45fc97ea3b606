#include "plumb/windowed/cramer_rao.hpp"

#include <cmath>

#include <Eigen/Dense>

#include "plumb/core/attitude.hpp"

namespace plumb::windowed {

double sigma_from_snr(double amplitude, double snr_db) {
  return amplitude / std::sqrt(2.0 * std::pow(10.0, snr_db / 10.0));
}

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

Vector6 model(double inc, double azi, double tf, const CrbCase& c) {
  Vector6 h;
  h.head<3>() = gravity_tool(inc, tf, c.g);
  h.tail<3>() = field_tool(inc, azi, tf, c.total_b, c.dip_deg * kDeg);
  return h;
}

}  // namespace

CrbResult cramer_rao_bound(const CrbCase& c) {
  CrbResult out;
  const long n = std::lround(c.duration_s * c.sample_rate_hz);
  if (n < 4 || !(c.sigma_accel > 0) || !(c.sigma_mag > 0)) return out;
  const double inc = c.inclination_deg * kDeg, azi = c.azimuth_deg * kDeg, tf0 = c.toolface0_deg * kDeg;
  const double rate = c.rpm * 2 * kPi / 60.0;
  Vector6 weight;
  weight << Eigen::Vector3d::Constant(1 / (c.sigma_accel * c.sigma_accel)),
      Eigen::Vector3d::Constant(1 / (c.sigma_mag * c.sigma_mag));
  // Central differences: the model is smooth and of order one, so a 1e-6 rad step is accurate
  // to ~1e-12 relative, far below what the bound needs.
  const double step = 1e-6;
  Eigen::Matrix4d info = Eigen::Matrix4d::Zero();
  for (long k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) / c.sample_rate_hz;
    const double tf = tf0 + rate * t;
    Eigen::Matrix<double, 6, 4> h;
    h.col(0) = (model(inc + step, azi, tf, c) - model(inc - step, azi, tf, c)) / (2 * step);
    h.col(1) = (model(inc, azi + step, tf, c) - model(inc, azi - step, tf, c)) / (2 * step);
    h.col(2) = (model(inc, azi, tf + step, c) - model(inc, azi, tf - step, c)) / (2 * step);
    h.col(3) = h.col(2) * t;  // dT/drate = t
    info += h.transpose() * weight.asDiagonal() * h;
  }
  Eigen::FullPivLU<Eigen::Matrix4d> lu(info);
  if (!lu.isInvertible()) return out;
  const Eigen::Matrix4d cov = lu.inverse();
  if (!(cov.diagonal().array() > 0).all()) return out;
  out.ok = true;
  out.inclination_deg = std::sqrt(cov(0, 0)) / kDeg;
  out.azimuth_deg = std::sqrt(cov(1, 1)) / kDeg;
  out.toolface0_deg = std::sqrt(cov(2, 2)) / kDeg;
  out.rpm = std::sqrt(cov(3, 3)) * 60.0 / (2 * kPi);
  return out;
}

}  // namespace plumb::windowed
