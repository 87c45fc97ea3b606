#include "plumb/strapdown/stream_faults.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

namespace plumb::strapdown {

namespace {

// The spread's memory: long enough to hold a few seconds of drilling, short enough to follow a
// change from still to turning.
constexpr double kSpreadMemoryS = 2.0;
// The rate across the axis held through a gap: its mean over about this long.
constexpr double kCrossRateMemoryS = 1.0;
// The spin's wander about its mean (stick-slip: periods of 2-10 s) over about this long.
constexpr double kSpinMemoryS = 5.0;
}  // namespace

void StreamFaults::reset() {
  recent_ = 0;
  spread_w2_ = spread_f2_ = spread_b2_ = 0;
  cross_rate_.setZero();
  cross_rate_var_ = 0;
  cross_rate_started_ = false;
  spin_mean_ = spin_var_ = 0;
  pending_att_ = pending_vel_ = 0;
  pending_axial_ = 0;
  pending_axis_.setZero();
  pending_force_.setZero();
  gap_said_ = repeat_said_ = false;
  notices_.clear();
}

// A white sequence x has var(x[k] - 2 x[k-1] + x[k-2]) = 6 var(x), and a trend that is locally a
// line or a slow curve drops out: what is left is how far a reading strays from what its
// neighbours say, which is what a lost reading's interpolation misses.
void StreamFaults::observe(const InputReading& in, double dt, double dt_nominal) {
  const bool even = dt_nominal > 0 && std::abs(dt - dt_nominal) < 0.25 * dt_nominal;
  if (!even) recent_ = 0;
  if (recent_ >= 2 && std::abs((r1_.t - r0_.t) - dt) < 0.25 * dt_nominal) {
    const double a = std::min(1.0, dt / kSpreadMemoryS);
    spread_w2_ += a * ((in.w - 2.0 * r1_.w + r0_.w).squaredNorm() / 18.0 - spread_w2_);
    spread_f2_ += a * ((in.f - 2.0 * r1_.f + r0_.f).squaredNorm() / 18.0 - spread_f2_);
    if (in.b && r1_.b && r0_.b) spread_b2_ += a * ((*in.b - 2.0 * *r1_.b + *r0_.b).squaredNorm() / 18.0 - spread_b2_);
  }
  r0_ = r1_;
  r1_ = Recent{in.t, in.w, in.f, in.b};
  recent_ = std::min(recent_ + 1, 2);
  // An exponential mean over kCrossRateMemoryS: its noise is the readings' times a / (2 - a).
  const double a = cross_rate_started_ && dt > 0 ? std::min(1.0, dt / kCrossRateMemoryS) : 1.0;
  cross_rate_ += a * (in.w.head<2>() - cross_rate_);
  cross_rate_var_ = a * a * spread_w2_ + (1 - a) * (1 - a) * cross_rate_var_;
  const double b = cross_rate_started_ && dt > 0 ? std::min(1.0, dt / kSpinMemoryS) : 1.0;
  spin_mean_ += b * (in.w.z() - spin_mean_);
  spin_var_ += b * ((in.w.z() - spin_mean_) * (in.w.z() - spin_mean_) - spin_var_);
  cross_rate_started_ = true;
}

// The lost readings are taken as unknowns with the spread the readings show, each standing for
// dt_nominal: over a gap of T they add spread^2 dt_nominal T to the attitude's (rate) and the
// velocity's (specific force) variance per axis. The filter's white noise already covers the
// sensors' own noise over T; this is the motion beyond it the readings would have shown.
// Across a gap of T the mechanization takes the rate as a line between the readings on either
// side. Where it changed (a spin that speeds up), the truth went from one to the other by a path
// the readings do not show: a monotone change keeps the integral within |change| T / 2 of the
// line's, taken as uniform (rms over sqrt(3)) along the change. The force is held in the navigation
// frame (gap_readings), so the attitude's error does not tilt it into the velocity during the gap:
// the turn is the attitude's alone (with a share in the velocity as well, the lateral-velocity
// updates after a gap read the velocity's agreement as a toolface known to 0.1 deg, 24 deg off).
void StreamFaults::bridge(const InputReading& prev, const InputReading& in, double dt_nominal,
                          const Eigen::Matrix3d& c_bn) {
  const double dt = in.t - prev.t, missing_s = dt - dt_nominal;
  // The force's share goes to the velocity at the gap's end (below), not as a random walk through
  // the epoch: a random walk would tie it to the position, and a lateral-velocity update after the
  // gap would move the position by metres for a velocity error the step made at its end.
  pending_att_ += spread_w2_ * dt_nominal * missing_s;
  // The rate across the axis held through the gap (gap_readings) holds its mean's noise: an angle
  // of that noise times the gap.
  pending_att_ += cross_rate_var_ * dt * dt;
  constexpr double kHalfOverRoot3 = 0.28867513459481287;  // 1 / (2 sqrt(3))
  Eigen::Vector3d dtheta = (kHalfOverRoot3 * dt) * (in.w - prev.w);
  // A string that sticks and slips turns at a rate that leaves the line between the readings either
  // side and comes back: at 60 rpm +-60 %, a 2 s gap whose ends read the same rate may hide a
  // turn of 200 deg. Its wander over the last seconds, times the gap, is what the gap may hide
  // about the axis (taken back by the field across the axis after it: axial_turn_seen).
  // Kept apart from the part across the axis: the field takes back the turn about the axis as
  // it was made (a turn of 190 deg taken back along an axis 0.1 deg from it leaves 0.3 deg of tilt
  // in the filter's noise, which the stop after the gap then reads as a tilt).
  pending_axial_ += std::copysign(std::hypot(dtheta.z(), std::sqrt(spin_var_) * dt), dtheta.z());
  pending_axis_ = c_bn.col(2);
  // Across the axis the size of the turn is known, not its direction: the rate's change was read
  // in a body that turned through the gap (stick-slip: by any angle), and the turn it hid is spread
  // over the directions the body faced. As one direction (a turn vector u, u u' added), the tilt the
  // gravity shows after the gap named the azimuth along with it: the lateral-velocity updates
  // within a second of the gap moved a tactical tool's azimuth by 0.07 deg, its sigma from 0.054 to
  // 0.022 deg (stick-slip family: azimuth RMS(error/sigma) 2.27). Every direction across the axis
  // alike instead (as attitude random walk through the epoch, about the axis too, where the axial
  // allowance above is far larger).
  pending_att_ += dtheta.head<2>().squaredNorm();
  pending_force_.diagonal().array() += spread_f2_ * dt_nominal * missing_s;
  recent_ = 0;
}

std::vector<InputReading> StreamFaults::gap_readings(const InputReading& prev, const InputReading& in,
                                                    const Eigen::Matrix3d& c_bn, double dt_nominal,
                                                    const Eigen::Vector3d& f_n, const Eigen::Vector3d& accel_bias,
                                                    const Eigen::Vector2d& cross_rate) {
  const double span = in.t - prev.t;
  const auto steps = static_cast<std::size_t>(std::max(1.0, std::round(span / (dt_nominal > 0 ? dt_nominal : span))));
  const Eigen::Vector3d f_start = c_bn.transpose() * f_n;
  std::vector<InputReading> readings(steps + 1, prev);
  readings.back() = in;
  Eigen::Quaterniond turned = Eigen::Quaterniond::Identity();  // the tool's frame now, in the frame before the gap
  for (std::size_t k = 0; k <= steps; ++k) {
    const double share = static_cast<double>(k) / static_cast<double>(steps);
    InputReading& r = readings[k];
    r.t = prev.t + share * span;
    r.w.z() = prev.w.z() + share * (in.w.z() - prev.w.z());
    r.w.head<2>() = cross_rate;
    if (k > 0) {
      const Eigen::Vector3d turn = (0.5 * span / static_cast<double>(steps)) * (readings[k - 1].w + r.w);
      const double angle = turn.norm();
      if (angle > 0) turned = (turned * Eigen::Quaterniond(Eigen::AngleAxisd(angle, turn / angle))).normalized();
    }
    // A vector fixed in the navigation frame, seen from a frame turned by `turned`, is turned back.
    r.f = turned.conjugate() * f_start + accel_bias;
  }
  return readings;
}

// The field's angle across the axis before and after the gap, each with the magnetometers' noise
// across it: a measurement of the turn with variance 2 (noise / field across)^2, weighed with the
// gap's allowance about the axis as a Kalman update of that one angle.
double StreamFaults::axial_turn_seen(double turn, double field_across, double field) {
  if (!(field_across > 0)) return 0;
  const double allowed = pending_axial_;
  constexpr double kMinFieldNoise2 = 1e-4;  // (0.01 uT)^2: a perfect simulated magnetometer
  // Beyond the noise, a calibrated triad's misalignment (a milliradian) tilts the whole field into
  // the part across the axis: an error the same before and after the gap only where the tool
  // turned by nothing.
  constexpr double kMisalignment = 1e-3;
  const double misaligned2 = kMisalignment * kMisalignment * field * field;
  const double measured2 = 2.0 * (std::max(spread_b2_, kMinFieldNoise2) + misaligned2) / (field_across * field_across);
  const double allowed2 = allowed * allowed;
  if (!(allowed2 + measured2 > 0)) return 0;
  const double gain = allowed2 / (allowed2 + measured2);
  pending_axial_ = std::sqrt(1.0 - gain) * allowed;
  return gain * turn;
}

void StreamFaults::add_to(UnseenMotionNoise& noise) {
  noise.turn.head<3>() += pending_axial_ * pending_axis_;
  noise.velocity += pending_force_;
  pending_axial_ = 0;
  pending_force_.setZero();
}

void StreamFaults::lost(double t, double dt, double dt_nominal, Counters& counters) {
  const double missing_s = dt - dt_nominal;
  count(counters, "dropouts");
  count(counters, "missing_samples", static_cast<std::uint64_t>(std::max(0.0, std::round(missing_s / dt_nominal))));
  if (!gap_said_) {
    gap_said_ = true;
    notices_.push_back(format("samples lost: %.3f s without a sample before t = %.3f s (about %.0f samples)", dt, t,
                              std::round(missing_s / dt_nominal)) +
                       "; gaps are bridged by the mechanization with the process noise of their length and of what "
                       "the lost readings could have shown, counted as dropouts and missing_samples, and the rows "
                       "after one say so");
  }
}

void StreamFaults::repeat(double t, bool same_stamp) {
  if (repeat_said_) return;
  repeat_said_ = true;
  notices_.push_back(format("a sample sent twice at t = %.3f s", t) +
                     (same_stamp ? " (the same time stamp)" : " (the same record under a later stamp)") +
                     ": repeats are dropped and counted (repeated_time, repeated_samples)");
}

ProcessNoise StreamFaults::widen(const ProcessNoise& base, double dt) {
  ProcessNoise noise = base;
  if (dt > 0 && (pending_att_ > 0 || pending_vel_ > 0)) {
    noise.gyro_arw = std::sqrt(noise.gyro_arw * noise.gyro_arw + pending_att_ / dt);
    noise.accel_vrw = std::sqrt(noise.accel_vrw * noise.accel_vrw + pending_vel_ / dt);
  }
  pending_att_ = pending_vel_ = 0;
  return noise;
}

std::vector<std::string> StreamFaults::take_notices() {
  std::vector<std::string> out;
  out.swap(notices_);
  return out;
}

}  // namespace plumb::strapdown
