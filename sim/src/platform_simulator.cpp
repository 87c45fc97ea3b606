// The sensors on the rotating platform: exact gravity, field and rate in the tool frame from the
// attitude C_n^b = R3(T) R2(I) R3(A), then vibration, the sensor error model and white noise.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/platform.hpp"
#include "plumb/sim/run_all.hpp"
#include "scenario_checks.hpp"

namespace plumb::sim {
namespace {

constexpr Refusal require_platform{"invalid scenario"};

constexpr double kReferenceTempC = 25.0;  // TriadErrors::bias_temp is relative to this

void validate(const Scenario& s) {
  require_platform(std::isfinite(s.sample_rate_hz) && s.sample_rate_hz > 0, "sample rate must be > 0 Hz");
  require_platform(std::isfinite(s.duration_s) && s.duration_s >= 0, "duration must be >= 0 s");
  require_platform(std::isfinite(s.g) && s.g > 0, "g must be > 0");
  require_platform(std::isfinite(s.total_b) && s.total_b >= 0, "total field must be >= 0");
  require_platform(std::isfinite(s.dip_deg) && std::abs(s.dip_deg) <= 90, "dip must be within [-90, 90] deg");
  require_platform(std::isfinite(s.inclination_deg) && s.inclination_deg >= 0 && s.inclination_deg <= 180,
          "inclination must be within [0, 180] deg");
  require_platform(std::isfinite(s.azimuth_deg) && std::isfinite(s.toolface0_deg), "azimuth and toolface must be finite");
  const auto& r = s.rotation;
  require_platform(std::isfinite(r.rpm) && std::isfinite(r.rpm_end) && std::isfinite(r.ramp_s), "rotation speeds must be finite");
  if (r.kind == ProfileKind::StopAndGo || r.kind == ProfileKind::StickSlip)
    require_platform(std::isfinite(r.period_s) && r.period_s > 0, "rotation period must be > 0 s");
  require_platform(s.sigma_accel() >= 0 && std::isfinite(s.sigma_accel()), "accelerometer noise must be finite and >= 0");
  require_platform(s.sigma_mag() >= 0 && std::isfinite(s.sigma_mag()), "magnetometer noise must be finite and >= 0");
  require_platform(std::isfinite(s.noise.sigma_gyro) && s.noise.sigma_gyro >= 0, "gyro noise must be finite and >= 0");
  const auto& v = s.vibration;
  const std::string vibration = vibration_problem(v);
  require_platform(vibration.empty(), vibration);
  require_platform(std::isfinite(v.shock_rate_hz) && v.shock_rate_hz >= 0, "shock rate must be >= 0 Hz");
  require_platform(std::isfinite(v.shock_peak) && std::isfinite(v.shock_duration_s) && v.shock_duration_s > 0,
          "shock peak and duration must be finite, duration > 0");
  require_platform(std::isfinite(s.temp_start_c) && std::isfinite(s.temp_end_c), "temperatures must be finite");
}

Eigen::Vector3d apply_errors(const TriadErrors& e, const Eigen::Vector3d& truth, double temp_c) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Identity() + e.misalignment;
  m.diagonal() += e.scale;
  return m * truth + e.bias + e.bias_temp * (temp_c - kReferenceTempC);
}

}  // namespace

PlatformSimulator::PlatformSimulator(const Scenario& scenario)
    : scenario_(scenario), rng_(scenario.seed), vib_rng_(scenario.seed ^ 0x9e3779b97f4a7c15ULL) {
  validate(scenario_);
  sigma_accel_ = scenario_.sigma_accel();
  sigma_mag_ = scenario_.sigma_mag();
  const auto& v = scenario_.vibration;
  tones_ = VibrationTones(v, vib_rng_);
  if (v.shock_rate_hz > 0 && v.shock_peak != 0)
    next_shock_ = std::exponential_distribution<double>(v.shock_rate_hz)(vib_rng_);
  else
    next_shock_ = std::numeric_limits<double>::infinity();
}

std::size_t PlatformSimulator::sample_count() const {
  return static_cast<std::size_t>(std::llround(scenario_.duration_s * scenario_.sample_rate_hz));
}

bool PlatformSimulator::done() const { return index_ >= sample_count(); }

Eigen::Vector3d PlatformSimulator::vibration_at(double t) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  const auto& v = scenario_.vibration;
  out.head<2>() = tones_.at(t);
  // Poisson arrivals; a later shock replaces one still ringing.
  const double duration = std::max(v.shock_duration_s, 2.0 / scenario_.sample_rate_hz);
  while (t >= next_shock_) {
    shock_start_ = next_shock_;
    shock_until_ = shock_start_ + duration;
    shock_dir_ = 2.0 * kPi * std::uniform_real_distribution<double>(0.0, 1.0)(vib_rng_);
    next_shock_ += std::exponential_distribution<double>(v.shock_rate_hz)(vib_rng_);
  }
  if (t >= shock_start_ && t < shock_until_) {
    const double a = v.shock_peak * std::sin(kPi * (t - shock_start_) / duration);
    out.x() += a * std::cos(shock_dir_);
    out.y() += a * std::sin(shock_dir_);
  }
  return out;
}

Sample PlatformSimulator::next(TruthSample* truth) {
  const Scenario& s = scenario_;
  const double t = static_cast<double>(index_) / s.sample_rate_hz;
  const double inc = s.inclination_deg * kDeg;
  const double azi = s.azimuth_deg * kDeg;
  const double tf = s.rotation.angle(t, s.toolface0_deg * kDeg);
  const double rpm = s.rotation.rpm_at(t);
  const double temp = s.temperature_at(t);

  const Eigen::Matrix3d c = c_nb(inc, azi, tf);
  const Eigen::Vector3d gravity = c * Eigen::Vector3d(0.0, 0.0, s.g);
  const Eigen::Vector3d field = c * field_ned(s.total_b, s.dip_deg * kDeg);
  const double lat = s.latitude_deg * kDeg;
  const Eigen::Vector3d earth_rate_ned(s.earth_rate * std::cos(lat), 0.0, -s.earth_rate * std::sin(lat));
  // The platform turns about tool z; a positive rate of T is a positive rotation about +z
  // (checked against dC/dt = -[w x] C in the tests).
  const Eigen::Vector3d rate = c * earth_rate_ned + Eigen::Vector3d(0.0, 0.0, rpm * 2.0 * kPi / 60.0);

  // Always draw all nine so the noise sequence does not depend on which sigmas are zero.
  Eigen::Vector3d n_a, n_m, n_w;
  for (int i = 0; i < 3; ++i) n_a[i] = normal_(rng_);
  for (int i = 0; i < 3; ++i) n_m[i] = normal_(rng_);
  for (int i = 0; i < 3; ++i) n_w[i] = normal_(rng_);

  Sample out;
  out.seq = index_;
  out.t = t;
  out.temp_c = temp;
  out.f = apply_errors(s.accel_errors, -gravity + vibration_at(t), temp) + sigma_accel_ * n_a;
  out.b = apply_errors(s.mag_errors, field, temp) + sigma_mag_ * n_m;
  out.flags = flags::kHasTemperature;
  if (s.with_gyro) {
    out.w = apply_errors(s.gyro_errors, rate, temp) + s.noise.sigma_gyro * n_w;
    out.flags |= flags::kHasGyro;
  }
  if (truth) {
    truth->t = t;
    truth->inclination_deg = s.inclination_deg;
    truth->azimuth_deg = wrap_deg_360(s.azimuth_deg);
    truth->toolface_deg = wrap_deg_360(tf / kDeg);
    truth->rpm = rpm;
  }
  ++index_;
  return out;
}

std::vector<Sample> PlatformSimulator::run(std::vector<TruthSample>* truth) { return run_all(*this, truth); }

}  // namespace plumb::sim
