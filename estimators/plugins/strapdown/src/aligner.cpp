#include "plumb/strapdown/aligner.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace plumb::strapdown {

using namespace index;

void Aligner::reset(const NavigatorConfig& config) {
  config_ = config;
  stats_.clear();
  accel_in_g_ = false;
  accel_in_g_level_ = 0;
  field_ = FieldReference{config_.field_uT, config_.dip};
  use_mag_ = false;
  azimuth_reference_ = config_.declination ? "true" : "magnetic";
}

bool Aligner::take(const InputReading& in, const StillnessState& still) {
  if (still.still) stats_.add(in.f, in.w, in.b, in.t);
  const bool long_enough = stats_.duration() >= config_.align_s;
  const bool period_over = still.ended && stats_.count() >= StillnessConfig::kMinWindowSamples;
  if ((still.still && long_enough) || period_over) return true;
  if (still.ended) stats_.clear();
  return false;
}

std::optional<Aligner::Coarse> Aligner::coarse(Counters& counters) {
  Coarse c;
  c.stats = stats_;
  stats_.clear();
  const Eigen::Vector3d f = c.stats.mean_f(), w = c.stats.mean_w();
  const double fn = f.norm();
  // Accelerometers in g instead of m/s^2 read |f| ~ 1 at rest.
  const double expected_g = config_.gravity.value_or(9.80665);
  if (std::abs(fn - expected_g) > 0.2 * expected_g) {
    accel_in_g_ = true;
    accel_in_g_level_ = fn;
    count(counters, "accel_in_g");
    return std::nullopt;
  }
  accel_in_g_ = false;
  c.g = config_.gravity.value_or(fn);
  const bool mag = config_.use_magnetometer && c.stats.mag_count() >= StillnessConfig::kMinWindowSamples;
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  if (mag) {
    b = c.stats.mean_b();
    if (!field_.total_uT) field_.total_uT = b.norm();
    if (!field_.dip) field_.dip = dip_of(f, b);
  }
  c.c_bn = initial_attitude(f, w, b, mag, c.heading_sd);
  return c;
}

// The attitude at alignment: tilt from the mean specific force, the heading from the earth rate
// (gyrocompass), a given azimuth, the magnetometer, or none (relative). Sets the azimuth reference
// and whether the magnetometer serves azimuth; heading_sd receives the heading's sigma.
Eigen::Matrix3d Aligner::initial_attitude(const Eigen::Vector3d& f, const Eigen::Vector3d& w,
                                          const Eigen::Vector3d& b, bool mag, double& heading_sd) {
  const double deg = std::numbers::pi / 180.0;
  heading_sd = 10.0 * deg;
  std::optional<Eigen::Matrix3d> c_bn;
  use_mag_ = false;
  if (config_.gyrocompass) {
    // The earth rate's horizontal part points at true north: the frame is true.
    c_bn = triad_attitude(f, w, 0.0);
    azimuth_reference_ = "true";
    use_mag_ = mag && config_.declination.has_value();
  } else if (config_.initial_azimuth) {
    c_bn = tilt_and_azimuth_attitude(f, *config_.initial_azimuth);
    azimuth_reference_ = "relative";
    heading_sd = std::max(config_.initial_azimuth_sd, 1e-6);
  } else if (mag) {
    c_bn = triad_attitude(f, b, config_.declination.value_or(0.0));
    azimuth_reference_ = config_.declination ? "true" : "magnetic";
    use_mag_ = true;
  } else {
    c_bn = tilt_and_azimuth_attitude(f, 0.0);
    azimuth_reference_ = "relative";
    heading_sd = 1e-6;
  }
  if (!c_bn) {
    c_bn = tilt_and_azimuth_attitude(f, 0.0);
    azimuth_reference_ = "relative";
  }
  return *c_bn;
}

// The filter's covariance at alignment, before its first measurements.
StateMatrix Aligner::initial_covariance(const Eigen::Vector3d& f, double heading_sd, double sd_mean_f, double depth_sd,
                                        bool lever_model, bool drilling_tool) const {
  const double deg = std::numbers::pi / 180.0;
  const double fn = f.norm();
  StateMatrix p0 = StateMatrix::Zero();
  const double tilt_sd = 2.0 * deg;
  p0.block<3, 3>(kAtt, kAtt).diagonal() << tilt_sd * tilt_sd, tilt_sd * tilt_sd, heading_sd * heading_sd;
  p0.block<3, 3>(kVel, kVel).diagonal().setConstant(1e-8);
  p0.block<3, 3>(kPos, kPos).diagonal().setConstant(1e-8);
  p0.block<3, 3>(kGyroBias, kGyroBias).diagonal().setConstant(config_.gyro_bias_sd * config_.gyro_bias_sd);
  p0.block<3, 3>(kAccelBias, kAccelBias).diagonal().setConstant(config_.accel_bias_sd * config_.accel_bias_sd);
  p0(kDistance, kDistance) = depth_sd * depth_sd;
  if (lever_model) p0.block<2, 2>(kLever, kLever).diagonal().setConstant(config_.lever_arm_sd * config_.lever_arm_sd);
  if (drilling_tool) {
    p0(kGyroScale, kGyroScale) = config_.gyro_scale_sd * config_.gyro_scale_sd;
    p0.block<2, 2>(kGyroLeak, kGyroLeak).diagonal().setConstant(config_.gyro_misalignment_sd * config_.gyro_misalignment_sd);
    // g_s and g_a are each the mean of two independent elements.
    p0.block<2, 2>(kGyroG, kGyroG).diagonal().setConstant(0.5 * config_.gyro_g_sensitivity_sd * config_.gyro_g_sensitivity_sd);
    if (use_mag_) p0(kMagAxial, kMagAxial) = config_.mag_axial_bias_sd * config_.mag_axial_bias_sd;
  }
  if (config_.gravity) {
    p0(kGravity, kGravity) = config_.gravity_sd * config_.gravity_sd;
  } else {
    // |mean f| = g + u.b + the mean's noise along u (u = mean f / |mean f|, up in the tool frame),
    // and the bias estimate starts at zero: dg = -u.dba + noise. Without that noise term the
    // filter would hold g exact to the bias and its inclination sigma would be 2x too small.
    const Eigen::Vector3d up = f / fn;
    const double var_b = config_.accel_bias_sd * config_.accel_bias_sd;
    p0(kGravity, kGravity) = var_b + sd_mean_f * sd_mean_f;
    p0.block<1, 3>(kGravity, kAccelBias) = -var_b * up.transpose();
    p0.block<3, 1>(kAccelBias, kGravity) = -var_b * up;
  }
  return p0;
}

}  // namespace plumb::strapdown
