#include <cmath>
#include <random>

#include <Eigen/LU>

#include "plumb/sim/turntable.hpp"

namespace plumb::sim {

namespace {

// A small deterministic normal generator on a state word (the stream is copyable and has no
// heavyweight engine to keep).
double normal(std::uint64_t& state) {
  std::mt19937_64 rng(state);
  state = rng();
  std::normal_distribution<double> n(0.0, 1.0);
  return n(rng);
}

}  // namespace

TurntableStream::TurntableStream(const SensorPackage& package, const Rig& rig)
    : package_(package), rig_(rig), noise_state_(rig.seed) {}

void TurntableStream::move_to(const StationPlan& plan) {
  Eigen::Vector3d f, b;
  true_vectors(rig_, plan, f, b);
  temperature_ = plan.temperature_c;
  target_a_ = package_.raw_accel(f, temperature_);
  target_m_ = package_.raw_mag(b, temperature_);
  if (!placed_) now_a_ = target_a_, now_m_ = target_m_, placed_ = true;
  from_a_ = now_a_;
  from_m_ = now_m_;
  moved_at_ = t_;
  tau_ = plan.settle_tau_s >= 0 ? plan.settle_tau_s : package_.settle_tau_s;
}

Sample TurntableStream::next() {
  const double dt = 1.0 / rig_.sample_rate_hz;
  const double decay = tau_ > 0 ? std::exp(-(t_ - moved_at_) / tau_) : 0.0;
  now_a_ = target_a_ + (from_a_ - target_a_) * decay;
  now_m_ = target_m_ + (from_m_ - target_m_) * decay;
  const Eigen::Matrix3d A = package_.truth.accelerometer.sensitivity.inverse();
  const Eigen::Matrix3d Am = package_.truth.magnetometer.sensitivity.inverse();
  Sample s;
  s.seq = seq_++;
  s.t = t_;
  Eigen::Vector3d ua = now_a_;
  for (int i = 0; i < 3; ++i) ua[i] += package_.accel_noise * A.row(i).norm() * normal(noise_state_);
  if (package_.accel_output == AccelOutput::PulseRate)
    for (int i = 0; i < 3; ++i) {
      const double before = std::floor(phase_[i]);
      phase_[i] += ua[i] * dt;
      ua[i] = (std::floor(phase_[i]) - before) / dt;
    }
  s.f = ua;
  s.b = now_m_;
  for (int i = 0; i < 3; ++i) s.b[i] += package_.mag_noise * Am.row(i).norm() * normal(noise_state_);
  s.temp_c = package_.raw_temperature(temperature_) + package_.thermometer_noise * normal(noise_state_);
  s.flags = flags::kHasTemperature;
  t_ += dt;
  return s;
}

}  // namespace plumb::sim
