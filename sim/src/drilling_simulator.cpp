// The sensors of the drilling tool sampled from the true trajectory: gyros w_ib = w_nb + C_n^b w_ie,
// accelerometers f = C_n^b (dv/dt + 2 w_ie x v - g_n), magnetometers C_n^b B_n (disturbed at chosen
// stops), the rig's measured depth; then biases, white noise, vibration and gyro saturation.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "drilling_detail.hpp"
#include "plumb/core/attitude.hpp"
#include "plumb/sim/drilling.hpp"
#include "plumb/sim/run_all.hpp"
#include "truth_of_state.hpp"

namespace plumb::sim {

namespace {

// The swell's phase from the seed alone (no draw from the noise streams: a run's noise does not
// depend on whether it heaves).
double heave_phase(std::uint64_t seed) {
  return 2.0 * kPi * static_cast<double>((seed * 0x9E3779B97F4A7C15ULL) >> 11) / 9007199254740992.0;
}

// Separate streams per purpose so that adding vibration or changing a bias does not change the
// noise sequence of the others.
constexpr std::uint64_t kVibrationStream = 0x9e3779b97f4a7c15ULL;
constexpr std::uint64_t kMagnetizationStream = 0xbf58476d1ce4e5b9ULL;
constexpr std::uint64_t kTemperatureSensorStream = 0xd6e8feb86659fd93ULL;

// Mud circulates while the string drills (every moving phase, ramps included) and stops otherwise.
TemperatureHistory history_of(const ToolTemperature& model, const DrillingTrajectory& trajectory) {
  std::vector<double> starts;
  std::vector<bool> circulating;
  for (const auto& phase : trajectory.phases()) {
    starts.push_back(phase.t0);
    circulating.push_back(phase.moving);
  }
  return TemperatureHistory(model, std::move(starts), std::move(circulating));
}

}  // namespace

DrillingSimulator::DrillingSimulator(const DrillingScenario& scenario)
    : scenario_(scenario),
      trajectory_(scenario.plan),
      imu_(scenario.grade, scenario.sample_rate_hz, scenario.seed, scenario.gyro_bias, scenario.accel_bias,
           scenario.earth_rate, scenario.latitude_deg),
      rng_(scenario.seed),
      vib_rng_(scenario.seed ^ kVibrationStream),
      temp_rng_(scenario.seed ^ kTemperatureSensorStream) {
  detail::validate(scenario_, trajectory_.stop_count());
  if (scenario_.temperature.enabled) temperature_ = history_of(scenario_.temperature, trajectory_);

  const auto& v = scenario_.vibration;
  tones_ = VibrationTones(v, vib_rng_);
  // Drawn from a stream of its own: the other noises stay what they were for the seed.
  std::mt19937_64 magnetization_rng(scenario_.seed ^ kMagnetizationStream);
  axial_bias_uT_ = scenario_.magnetometer.axial_bias_uT.value_or(
      scenario_.magnetometer.axial_bias_sd_uT * std::normal_distribution<double>(0.0, 1.0)(magnetization_rng));
  next_shock_ = v.shock_rate_hz > 0 && v.shock_peak != 0
                    ? std::exponential_distribution<double>(v.shock_rate_hz)(vib_rng_)
                    : std::numeric_limits<double>::infinity();
}

std::size_t DrillingSimulator::sample_count() const {
  return static_cast<std::size_t>(std::llround(trajectory_.duration_s() * scenario_.sample_rate_hz));
}

bool DrillingSimulator::done() const { return index_ >= sample_count(); }

double DrillingSimulator::time_of(std::size_t index) const {
  return static_cast<double>(index) / scenario_.sample_rate_hz;
}

double DrillingSimulator::temperature_at(double t) const {
  return scenario_.temperature.enabled ? temperature_.at(t) : scenario_.temperature.start_c;
}

Eigen::Vector3d DrillingSimulator::field_at(const DrillingState& st) const {
  double total = scenario_.total_b, dip = scenario_.dip_deg;
  const auto& phase = trajectory_.phases()[st.phase];
  if (st.still && phase.stop_index)
    for (const auto& d : scenario_.magnetometer.disturbances)
      if (d.stop_index == *phase.stop_index) {
        total += d.delta_total_uT;
        dip += d.delta_dip_deg;
      }
  return st.c_nb * field_ned(total, dip * kDeg);
}

Sample DrillingSimulator::next(TruthSample* truth) {
  const double t = time_of(index_);
  const DrillingState st = trajectory_.at(t);
  const Eigen::Vector3d vibration = vibration_at(t, st.drive);

  // Always draw all ten so the noise sequence does not depend on which sigmas are zero.
  Eigen::Vector3d n_w, n_a, n_m;
  for (int i = 0; i < 3; ++i) n_w[i] = normal_(rng_);
  for (int i = 0; i < 3; ++i) n_a[i] = normal_(rng_);
  for (int i = 0; i < 3; ++i) n_m[i] = normal_(rng_);
  const double n_d = normal_(rng_);

  Sample out;
  out.seq = index_;
  out.t = t;
  const ToolTemperature& temp = scenario_.temperature;
  const double temp_c = temperature_at(t);
  imu_.measure(st.w_nb, st.c_nb, st.acceleration, st.velocity, scenario_.g, vibration, n_w, n_a, out,
               temp_c - temp.start_c);
  if (temp.enabled) {
    // A distribution of its own: normal_ keeps a spare draw of the noise stream.
    double reading = temp_c + temp.sensor_sigma_c * std::normal_distribution<double>(0.0, 1.0)(temp_rng_);
    if (temp.sensor_quantum_c > 0) reading = temp.sensor_quantum_c * std::round(reading / temp.sensor_quantum_c);
    out.temp_c = reading;
    out.flags |= flags::kHasTemperature;
  }
  if (scenario_.magnetometer.present) {
    out.b = field_at(st) + scenario_.magnetometer.sigma_uT * n_m + Eigen::Vector3d(0.0, 0.0, axial_bias_uT_);
  }
  if (scenario_.depth.present) {
    double depth = st.depth_m + scenario_.depth.sigma_m * n_d;
    if (scenario_.depth.heave_amplitude_m > 0) {
      depth += scenario_.depth.heave_amplitude_m *
               std::sin(2.0 * kPi * t / scenario_.depth.heave_period_s + heave_phase(scenario_.seed));
    }
    const double q = scenario_.depth.quantum_m;
    if (q > 0) depth = q * std::round(depth / q);
    out.depth_m = depth;
    out.flags |= flags::kHasDepth;
  }
  if (truth) fill_truth(st, t, st.depth_m, *truth);
  ++index_;
  return out;
}

std::vector<Sample> DrillingSimulator::run(std::vector<TruthSample>* truth) { return run_all(*this, truth); }

}  // namespace plumb::sim
