// The IMU of one simulated run (imu_model.hpp): biases, noise, clipping, earth rate.
#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/imu_model.hpp"

namespace plumb::sim {
namespace {

// Its own stream, so that an explicit gyro bias or a change of grade leaves the noise unchanged.
constexpr std::uint64_t kBiasStream = 0xc2b2ae3d27d4eb4fULL;
// The temperature coefficients' own stream: drawing them leaves the biases and the noise as they were.
constexpr std::uint64_t kTemperatureCoefficientStream = 0x94d049bb133111ebULL;
constexpr double kCoefficientSpread = 0.25;  // 1 sigma, as a fraction of the stated coefficient

Eigen::Vector3d draw_coefficient(std::mt19937_64& rng, double stated) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector3d k;
  for (int i = 0; i < 3; ++i) k[i] = stated * (1.0 + kCoefficientSpread * normal(rng));
  return k;
}

Eigen::Vector3d draw_bias(std::mt19937_64& rng, double sigma) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector3d b;
  for (int i = 0; i < 3; ++i) b[i] = sigma * normal(rng);
  return b;
}

}  // namespace

ImuModel::ImuModel(const ImuGrade& grade, double rate_hz, std::uint64_t seed,
                   const std::optional<Eigen::Vector3d>& gyro_bias, const std::optional<Eigen::Vector3d>& accel_bias,
                   double earth_rate, double latitude_deg) {
  // Both drawn always, so an explicit gyro bias leaves the drawn accelerometer bias unchanged.
  std::mt19937_64 bias_rng(seed ^ kBiasStream);
  const Eigen::Vector3d gyro_drawn = draw_bias(bias_rng, grade.gyro_bias_sigma());
  const Eigen::Vector3d accel_drawn = draw_bias(bias_rng, grade.accel_bias_sigma());
  gyro_bias_ = gyro_bias.value_or(gyro_drawn);
  accel_bias_ = accel_bias.value_or(accel_drawn);
  std::mt19937_64 temperature_rng(seed ^ kTemperatureCoefficientStream);
  gyro_temp_ = draw_coefficient(temperature_rng, grade.gyro_bias_temp());
  accel_temp_ = draw_coefficient(temperature_rng, grade.accel_bias_temp());
  const double dt = 1.0 / rate_hz;
  sigma_gyro_ = grade.gyro_noise_sigma(dt);
  sigma_accel_ = grade.accel_noise_sigma(dt);
  gyro_range_ = grade.gyro_range();
  accel_range_ = grade.accel_range();
  const double lat = latitude_deg * kDeg;
  earth_rate_ned_ = earth_rate * Eigen::Vector3d(std::cos(lat), 0.0, -std::sin(lat));
}

void ImuModel::measure(const Eigen::Vector3d& w_nb, const Eigen::Matrix3d& c_nb, const Eigen::Vector3d& acceleration,
                       const Eigen::Vector3d& velocity, double g, const Eigen::Vector3d& extra_f,
                       const Eigen::Vector3d& n_w, const Eigen::Vector3d& n_a, Sample& out,
                       double delta_temp_c) const {
  const Eigen::Vector3d g_n(0.0, 0.0, g);
  const Eigen::Vector3d w_ib = w_nb + c_nb * earth_rate_ned_;
  const Eigen::Vector3d f = c_nb * (acceleration + 2.0 * earth_rate_ned_.cross(velocity) - g_n) + extra_f;
  out.flags |= flags::kHasGyro;
  out.w = w_ib + gyro_bias_ + sigma_gyro_ * n_w;
  if (delta_temp_c != 0) out.w += delta_temp_c * gyro_temp_;
  for (int i = 0; i < 3; ++i)
    if (std::abs(out.w[i]) > gyro_range_) {
      out.w[i] = std::copysign(gyro_range_, out.w[i]);
      out.flags |= flags::kGyroSaturated;
    }
  out.f = f + accel_bias_ + sigma_accel_ * n_a;
  if (delta_temp_c != 0) out.f += delta_temp_c * accel_temp_;
  for (int i = 0; i < 3; ++i)
    if (std::abs(out.f[i]) > accel_range_) {
      out.f[i] = std::copysign(accel_range_, out.f[i]);
      out.flags |= flags::kAccelSaturated;
    }
}

}  // namespace plumb::sim
