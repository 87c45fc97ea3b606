#include "plumb/strapdown/temperature_drift.hpp"

#include <algorithm>
#include <cmath>

namespace plumb::strapdown {

namespace {

// The noise's temperature is a mean over this long (its changes take minutes); the correction
// takes each reading as it is (its noise times a coefficient is far below the sensors').
constexpr double kSmoothingS = 2.0;
constexpr double kAccountStepC = 0.1;      // noise added in steps of this much change
constexpr double kUnknownNoticeC = 5.0;    // a change this large without coefficients is said

}  // namespace

void TemperatureDrift::reset(const NavigatorConfig& config) {
  config_ = config;
  t0_.reset();
  smooth_ = last_t_ = accounted_ = pending_ = largest_ = 0;
  const bool gyro_stated = config.gyro_bias_temp != 0, accel_stated = config.accel_bias_temp != 0;
  gyro_k_ = config.gyro_bias_temp;
  accel_k_ = config.accel_bias_temp;
  gyro_sd_ = gyro_stated ? config.bias_temp_sd * std::abs(config.gyro_bias_temp) : config.default_gyro_bias_temp;
  accel_sd_ = accel_stated ? config.bias_temp_sd * std::abs(config.accel_bias_temp) : config.default_accel_bias_temp;
  stated_notice_ = unknown_notice_ = false;
  notices_.clear();
}

void TemperatureDrift::correct(InputReading& in, Counters& counters) {
  if (!config_.use_temperature || !in.temp_c) return;
  count(counters, "temperature_readings");
  const double temp = *in.temp_c;
  if (!t0_) {
    t0_ = smooth_ = temp;
    if (gyro_k_ != 0 || accel_k_ != 0) {
      stated_notice_ = true;
      notices_.push_back(format("readings corrected for the tool's temperature from %.2f degC at t = %.3f s", temp,
                                in.t) +
                         format(" by %.4g deg/h/degC (gyros) and %.4g mg/degC (accelerometers)",
                                gyro_k_ * kRadPerSecToDegPerHour, accel_k_ / 9.80665e-3) +
                         "; what the coefficients are not known to (bias_temp_sd of them) widens the biases' sigma as "
                         "the temperature changes (counter temperature_corrected)");
    }
  } else {
    const double dt = in.t - last_t_;
    if (dt > 0) smooth_ += (temp - smooth_) * std::min(1.0, dt / kSmoothingS);
  }
  last_t_ = in.t;
  const double change = smooth_ - *t0_;
  largest_ = std::max(largest_, std::abs(change));
  if (std::abs(change - accounted_) >= kAccountStepC) {
    pending_ += std::abs(change * change - accounted_ * accounted_);
    accounted_ = change;
  }
  if (gyro_k_ != 0 || accel_k_ != 0) {
    const double now = temp - *t0_;
    in.w.array() -= gyro_k_ * now;
    in.f.array() -= accel_k_ * now;
    count(counters, "temperature_corrected");
  }
  if (!unknown_notice_ && (gyro_k_ == 0 || accel_k_ == 0) && largest_ >= kUnknownNoticeC) {
    unknown_notice_ = true;
    notices_.push_back(format("the tool's temperature changed by %.1f degC since the first reading (t = %.3f s)",
                              change, in.t) +
                       " and the biases' temperature coefficients are not all given: their sigma is widened by the " +
                       format("grade's typical %.3g deg/h/degC and %.3g mg/degC as it changes", gyro_sd_ * kRadPerSecToDegPerHour,
                              accel_sd_ / 9.80665e-3) +
                       "; give gyro_bias_temp_dph_per_c and accel_bias_temp_mg_per_c (datasheet) to correct the readings");
  }
}

ProcessNoise TemperatureDrift::widen(const ProcessNoise& base, double dt) {
  if (!(pending_ > 0) || !(dt > 0)) return base;
  ProcessNoise noise = base;
  noise.gyro_bias_walk = std::sqrt(noise.gyro_bias_walk * noise.gyro_bias_walk + gyro_sd_ * gyro_sd_ * pending_ / dt);
  noise.accel_bias_walk =
      std::sqrt(noise.accel_bias_walk * noise.accel_bias_walk + accel_sd_ * accel_sd_ * pending_ / dt);
  pending_ = 0;
  return noise;
}

std::string TemperatureDrift::row_warning() const {
  if (!t0_ || std::abs(smooth_ - *t0_) < kUnknownNoticeC || (gyro_k_ != 0 && accel_k_ != 0)) return {};
  return format("tool temperature %+.1f degC since the first reading without its coefficients: bias sigma widened",
                smooth_ - *t0_);
}

std::vector<std::string> TemperatureDrift::take_notices() {
  std::vector<std::string> out;
  out.swap(notices_);
  return out;
}

}  // namespace plumb::strapdown
