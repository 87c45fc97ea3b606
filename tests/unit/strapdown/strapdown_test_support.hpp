// Helpers of the navigator's tests: small generators (a still or constantly turning tool on the
// rotating earth), running a Navigator, and comparing its rows with the simulator's truth.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "plumb/core/attitude.hpp"
#include "plumb/core/estimate.hpp"
#include "plumb/core/sample.hpp"
#include "plumb/strapdown/earth.hpp"
#include "plumb/strapdown/navigator.hpp"

namespace plumb::strapdown::test {

struct StillTool {
  double inclination_deg = 60, azimuth_deg = 40, toolface_deg = 30;
  double latitude_deg = 35, g = 9.80665, total_b = 50, dip_deg = 60;
  Eigen::Vector3d gyro_bias = Eigen::Vector3d::Zero();   // rad/s
  Eigen::Vector3d accel_bias = Eigen::Vector3d::Zero();  // m/s^2
  double sigma_gyro = 0, sigma_accel = 0, sigma_mag = 0; // per sample
  double rate_hz = 100, duration_s = 60, t0 = 0;
  bool magnetometer = true;
  std::uint64_t seed = 1;

  Eigen::Matrix3d c_nb() const {
    return plumb::c_nb(inclination_deg * kDeg, azimuth_deg * kDeg, toolface_deg * kDeg);
  }
  std::vector<Sample> samples() const {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n(0.0, 1.0);
    auto noise = [&](double s) { return Eigen::Vector3d(s * n(rng), s * n(rng), s * n(rng)); };
    const Eigen::Matrix3d c = c_nb();
    const Eigen::Vector3d w = c * earth_rate_ned(latitude_deg * kDeg);
    const Eigen::Vector3d f = -c * Eigen::Vector3d(0, 0, g);
    const Eigen::Vector3d b = c * field_ned(total_b, dip_deg * kDeg);
    const auto count = static_cast<std::size_t>(std::llround(duration_s * rate_hz));
    std::vector<Sample> out(count);
    for (std::size_t k = 0; k < count; ++k) {
      Sample& s = out[k];
      s.seq = k;
      s.t = t0 + static_cast<double>(k) / rate_hz;
      s.w = w + gyro_bias + noise(sigma_gyro);
      s.f = f + accel_bias + noise(sigma_accel);
      s.b = magnetometer ? Eigen::Vector3d(b + noise(sigma_mag)) : Eigen::Vector3d::Zero();
      s.flags = flags::kHasGyro;
    }
    return out;
  }
};

inline std::vector<Estimate> run(Navigator& nav, const std::vector<Sample>& samples, bool flush = true) {
  std::vector<Estimate> rows;
  for (const Sample& s : samples) nav.push(s, rows);
  if (flush) nav.flush(rows);
  return rows;
}

// Attitude error (rad) of the estimate against a true C_n^b, as the rotation vector phi with
// C_b^n(est) = exp([phi x]) C_b^n(true), in the navigation frame.
inline Eigen::Vector3d attitude_error(const Eigen::Quaterniond& q_est, const Eigen::Matrix3d& c_nb_true) {
  const Eigen::Matrix3d e = q_est.toRotationMatrix() * c_nb_true;  // C_b^n(est) C_n^b(true)
  const Eigen::AngleAxisd aa(e);
  return aa.angle() * aa.axis();
}

}  // namespace plumb::strapdown::test
