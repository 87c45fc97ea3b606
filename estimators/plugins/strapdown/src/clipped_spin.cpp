#include "plumb/strapdown/clipped_spin.hpp"

#include <algorithm>
#include <cmath>

#include "plumb/strapdown/rotation.hpp"

namespace plumb::strapdown {

namespace {

// How fast the spin changes, 1 sigma (rad/s^2): stick-slip swings a 60 rpm string by 60 % every
// 2-8 s, 3-12 rad/s^2. With the angle's noise it sets the loop's gains (an alpha-beta tracker's
// steady state for white acceleration): a quiet angle (the magnetometers') is followed closely, a
// noisy one (the accelerometers' under tenths of g of vibration) smoothly.
constexpr double kSpinAcceleration = 30.0;
// The innovations' spread is remembered over this long; the loop's error decorrelates in it too.
constexpr double kSpreadMemoryS = 1.0;
// The angle's noise before any innovation was seen (rad): a magnetometer's across a field of tens
// of microtesla, an accelerometer's under a drilling tool's vibration.
constexpr double kFirstSpread[2] = {0.1, 0.01};
constexpr double kMinSpread = 1e-4;

// The alpha-beta tracker's gains for a tracking index lambda (Kalata, 1984).
std::pair<double, double> tracker_gains(double lambda) {
  const double root = std::sqrt(lambda * lambda + 8.0 * lambda);
  const double alpha = -(lambda * lambda + 8.0 * lambda - (lambda + 4.0) * root) / 8.0;
  const double beta = (lambda * lambda + 4.0 * lambda - lambda * root) / 4.0;
  return {std::clamp(alpha, 0.0, 1.0), std::clamp(beta, 0.0, 1.0)};
}

double across_angle(const Eigen::Vector3d& v) { return std::atan2(v.y(), v.x()); }
bool across_axis(const Eigen::Vector3d& v) { return v.head<2>().norm() >= ClippedSpin::kMinAcrossAxis * v.norm(); }

}  // namespace

void ClippedSpin::reset(const NavigatorConfig& config) {
  config_ = config;
  tracking_ = false;
  phase_ = rate_ = variance_ = 0;
  for (int k = 0; k < 2; ++k) innovation2_[k] = kFirstSpread[k] * kFirstSpread[k];
}

std::optional<ClippedSpin::Spin> ClippedSpin::through(const InputReading& in, const InputReading& prev, double dt,
                                                      const Eigen::Matrix3d& c_bn, double g) {
  if (!(dt > 0)) return std::nullopt;
  // The field's part across the axis (far better than gravity's: no vibration in it), where the
  // axis is not along the field; else gravity's, where the axis is not near vertical.
  const bool mag = in.b && prev.b && across_axis(*in.b) && across_axis(*prev.b);
  // Gravity's reaction (up, -z in NED) seen from the tool at the reading before.
  const Eigen::Vector3d up_in_tool = -g * c_bn.row(2).transpose();
  if (!mag && !across_axis(up_in_tool)) {
    tracking_ = false;
    return std::nullopt;
  }
  const int source = mag ? 1 : 0;
  // The truth lies beyond the range on the side the reading clipped (a held reading: the last
  // good rate's side), up to the fastest a tool turns.
  const double side = in.w.z() < 0 ? -1.0 : 1.0;
  const double slowest = std::min(config_.gyro_range, config_.gyro_rate_max);
  const auto within = [&](double w) { return side * std::clamp(side * w, slowest, config_.gyro_rate_max); };
  if (!tracking_ || source != source_) {
    tracking_ = true;
    source_ = source;
    phase_ = mag ? across_angle(*prev.b) : across_angle(up_in_tool);
    rate_ = within(prev.w.z());
  }
  double& spread2 = innovation2_[source];
  const auto [alpha, beta] = tracker_gains(kSpinAcceleration * dt * dt / std::sqrt(std::max(spread2, kMinSpread * kMinSpread)));
  // The tool turning by +a about its axis turns what is fixed in the navigation frame by -a in the
  // tool's.
  const double predicted = phase_ - rate_ * dt;
  const double innovation = wrap_pi(across_angle(mag ? *in.b : in.f) - predicted);
  const double rate = within(rate_ - beta * innovation / dt);
  const double turned = rate_ * dt - alpha * innovation;
  const Spin spin{rate, turned - 0.5 * (prev.w.z() + rate) * dt};
  phase_ = wrap_pi(predicted + alpha * innovation);
  rate_ = rate;
  const double keep = std::min(1.0, dt / kSpreadMemoryS);
  spread2 += keep * (innovation * innovation - spread2);
  // The loop's phase error: a share alpha of the innovations' spread, decorrelating over the memory.
  variance_ += alpha * spread2 * keep;
  return spin;
}

double ClippedSpin::take_variance() {
  const double v = variance_;
  variance_ = 0;
  return v;
}

std::optional<double> unseen_turn_across_gap(const InputReading& prev, const InputReading& in,
                                             const Eigen::Matrix3d& c_before, const Eigen::Matrix3d& c_after) {
  constexpr double kGapMinAcrossAxis = 0.05;
  const auto across_enough = [](const Eigen::Vector3d& b) { return b.head<2>().norm() >= kGapMinAcrossAxis * b.norm(); };
  if (!prev.b || !in.b || !across_enough(*prev.b) || !across_enough(*in.b)) return std::nullopt;
  // The field fixed in the navigation frame, seen after the mechanization's turn: the tool turned
  // further by a about its axis sees it a further -a across the axis.
  const Eigen::Vector3d predicted = c_after.transpose() * (c_before * *prev.b);
  return wrap_pi(across_angle(predicted) - across_angle(*in.b));
}

}  // namespace plumb::strapdown
