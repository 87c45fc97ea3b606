#include "plumb/strapdown/sensor_range.hpp"

#include <algorithm>
#include <cmath>

namespace plumb::strapdown {

namespace {

// The truth beyond the range is anywhere in [range, plausible maximum]: its root mean square
// about the clipped value, B / sqrt(3) for an excess up to B, covers both the excess's mean and
// its spread.
constexpr double kRmsOfUniformExcess = 0.57735026918962576;  // 1 / sqrt(3)

}  // namespace

void SensorRange::reset(const NavigatorConfig& config) {
  config_ = config;
  attitude_.setZero();
  velocity_.setZero();
  row_accel_ = row_gyro_ = 0;
  accel_said_ = gyro_said_ = false;
  notices_.clear();
}

void SensorRange::seen(const InputReading& in) {
  if (in.clipped == 0) return;
  if (!accel_said_ && (in.clipped & 7u) != 0) {
    accel_said_ = true;
    notices_.push_back(format("accelerometer clipped at its range (%.1f g) at t = %.3f s", config_.accel_range / 9.80665,
                              in.t) +
                       ": what a shock held beyond it is unknown; with accel_shock_max_g each clipped reading widens the "
                       "velocity's sigma by up to that less the range; the rows that hold one say so (counter "
                       "accel_clipped)");
  }
  if (!gyro_said_ && (in.clipped & 56u) != 0) {
    gyro_said_ = true;
    notices_.push_back(format("gyro clipped at its range (%.0f deg/s) at t = %.3f s", config_.gyro_range * kRadToDeg,
                              in.t) +
                       ": the turn beyond it is unknown, so each clipped reading widens the attitude's sigma about that "
                       "axis by up to gyro_rate_max_dps less the range, except a drilling tool's about its own axis, "
                       "whose spin is followed from the magnetometers (or the accelerometers) with the sigma that "
                       "costs; the rows that hold one say so (counter gyro_clipped)");
  }
}

// A held reading (flagged saturated: the last good value stands in) may miss the whole plausible
// value, a clipped one only what lies beyond the range.
void SensorRange::integrate(const InputReading& in, double dt, const Eigen::Matrix3d& c_bn, const char* spin_followed_by) {
  const bool spin_followed = spin_followed_by != nullptr;
  if ((in.clipped == 0 && !spin_followed) || !(dt > 0)) return;
  // The clipped axes' columns of c_bn; the others zero.
  const auto axes = [&c_bn](unsigned bits) {
    Eigen::Matrix3d m = c_bn;
    for (int i = 0; i < 3; ++i)
      if ((bits & (1u << i)) == 0) m.col(i).setZero();
    return m;
  };
  if ((in.clipped & 7u) != 0) {
    ++row_accel_;
    const double beyond = std::max(0.0, config_.accel_shock_max - (in.accel_bad ? 0.0 : config_.accel_range));
    velocity_.noalias() += (kRmsOfUniformExcess * beyond * dt) * axes(in.clipped & 7u);
  }
  const unsigned gyro_axes = ((in.clipped >> 3) & 7u) & (spin_followed ? 3u : 7u);
  if (spin_followed) {
    ++row_followed_;
    followed_by_ = spin_followed_by;
  }
  if (gyro_axes != 0) {
    ++row_gyro_;
    const double beyond = std::max(0.0, config_.gyro_rate_max - (in.gyro_bad ? 0.0 : config_.gyro_range));
    attitude_.noalias() += (kRmsOfUniformExcess * beyond * dt) * axes(gyro_axes);
  }
}

void SensorRange::add_to(UnseenMotionNoise& noise) {
  if (!velocity_.isZero(0.0)) noise.velocity += velocity_ * velocity_.transpose();
  if (!attitude_.isZero(0.0)) noise.attitude += attitude_ * attitude_.transpose();
  velocity_.setZero();
  attitude_.setZero();
}

std::string SensorRange::row_warning() const {
  std::string out;
  if (row_accel_ > 0) {
    out = format("accelerometer clipped at %.1f g in %.0f readings: sigma widened", config_.accel_range / 9.80665,
                 static_cast<double>(row_accel_));
  }
  if (row_gyro_ > 0) {
    out += (out.empty() ? "" : "; ") + format("gyro clipped at %.0f deg/s in %.0f readings: sigma widened",
                                              config_.gyro_range * kRadToDeg, static_cast<double>(row_gyro_));
  }
  if (row_followed_ > 0) {
    out += (out.empty() ? "" : "; ") +
           format("axial gyro at its range (%.0f deg/s) in %.0f readings: the spin followed from the ",
                  config_.gyro_range * kRadToDeg, static_cast<double>(row_followed_)) +
           followed_by_;
  }
  return out;
}

std::vector<std::string> SensorRange::take_notices() {
  std::vector<std::string> out;
  out.swap(notices_);
  return out;
}

}  // namespace plumb::strapdown
