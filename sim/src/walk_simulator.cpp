// The sensors of the foot-mounted IMU sampled from the true walk, by the drilling simulator's
// formulas: gyros w_ib = w_nb + C_n^b w_ie, accelerometers f = C_n^b (dv/dt + 2 w_ie x v - g_n),
// magnetometers C_n^b B_n; then the grade's biases, white noise and gyro saturation.
#include <cmath>

#include <Eigen/Geometry>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/run_all.hpp"
#include "truth_of_state.hpp"
#include "walk_detail.hpp"

namespace plumb::sim {
WalkSimulator::WalkSimulator(const WalkScenario& scenario)
    : scenario_(scenario),
      path_(scenario),
      imu_(scenario.grade, scenario.sample_rate_hz, scenario.seed, scenario.gyro_bias, scenario.accel_bias,
           scenario.earth_rate, scenario.latitude_deg),
      rng_(scenario.seed) {
  detail::validate_walk_sensors(scenario_);
  field_ned_ = field_ned(scenario_.total_b, scenario_.dip_deg * kDeg);
}

std::size_t WalkSimulator::sample_count() const {
  return static_cast<std::size_t>(std::llround(path_.duration_s() * scenario_.sample_rate_hz));
}

bool WalkSimulator::done() const { return index_ >= sample_count(); }

double WalkSimulator::time_of(std::size_t index) const { return static_cast<double>(index) / scenario_.sample_rate_hz; }

Sample WalkSimulator::next(TruthSample* truth) {
  const double t = time_of(index_);
  const WalkState st = path_.at(t);

  // Always draw all nine so the noise sequence does not depend on which sigmas are zero.
  Eigen::Vector3d n_w, n_a, n_m;
  for (int i = 0; i < 3; ++i) n_w[i] = normal_(rng_);
  for (int i = 0; i < 3; ++i) n_a[i] = normal_(rng_);
  for (int i = 0; i < 3; ++i) n_m[i] = normal_(rng_);

  Sample out;
  out.seq = index_;
  out.t = t;
  imu_.measure(st.w_nb, st.c_nb, st.acceleration, st.velocity, scenario_.g, Eigen::Vector3d::Zero(), n_w, n_a, out);
  if (scenario_.magnetometer) out.b = st.c_nb * field_ned_ + scenario_.mag_sigma_uT * n_m;
  if (truth) fill_truth(st, t, 0, *truth);
  ++index_;
  return out;
}

std::vector<Sample> WalkSimulator::run(std::vector<TruthSample>* truth) { return run_all(*this, truth); }

}  // namespace plumb::sim
