// Runs the navigator over DrillingSimulator runs and measures it against the truth.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/drilling.hpp"
#include "plumb/strapdown/navigator.hpp"
#include "plumb/strapdown/parameters.hpp"

namespace plumb::strapdown::test {

struct RunMetrics {
  std::size_t rows = 0, valid_rows = 0;
  double max_inc_err_deg = 0, max_azi_err_deg = 0, max_tf_err_deg = 0;
  double max_axis_err_deg = 0;  // the angle between the estimated and the true tool axis
  double end_position_err_m = 0, drilled_m = 0;
  double sum_z2 = 0;   // sum of (error / sigma)^2 over I, A, T of every valid row
  double n_z = 0;
  double sum_z2_angle[3] = {0, 0, 0}, n_z_angle[3] = {0, 0, 0};
  double count_z_above_3 = 0;
  double end_azi_err_deg = 0, end_azi_sd_deg = 0;
  double end_position_z2 = 0;  // sum over north, east, down of (error / sigma)^2 at the last row
  double max_attitude_err_deg() const { return std::max({max_inc_err_deg, max_azi_err_deg, max_tf_err_deg}); }
  double end_position_pct() const { return drilled_m > 0 ? 100.0 * end_position_err_m / drilled_m : 0.0; }
  double rms_z() const { return n_z > 0 ? std::sqrt(sum_z2 / n_z) : 0.0; }
  double end_position_rms_z() const { return std::sqrt(end_position_z2 / 3); }
  // Of one angle: 0 inclination, 1 azimuth, 2 toolface.
  double rms_z_angle(int k) const { return n_z_angle[k] > 0 ? std::sqrt(sum_z2_angle[k] / n_z_angle[k]) : 0.0; }
  // Adds another run's attitude (error / sigma)^2: rms_z() is then over both.
  void pool_z(const RunMetrics& other) {
    sum_z2 += other.sum_z2;
    n_z += other.n_z;
  }
};

// Three rotary segments of 4 m at 0.03 m/s, each followed by a 60 s stop, instead of the plan's.
inline void three_rotary_segments(sim::DrillingScenario& s, double rpm) {
  s.plan.segments.clear();
  for (int i = 0; i < 3; ++i) {
    s.plan.segments.push_back(sim::DrillSegment::rotary(4, 0.03, rpm));
    s.plan.segments.push_back(sim::DrillSegment::stop(60));
  }
}

// Readings as an integrating sensor reports them: the mean of every `per_reading` samples, stamped
// at the middle (flags and depth as the last sample had them).
inline std::vector<Sample> read_as_means(const std::vector<Sample>& fine, std::size_t per_reading) {
  std::vector<Sample> means;
  for (std::size_t k = 0; k + per_reading <= fine.size(); k += per_reading) {
    Sample m = fine[k + per_reading - 1];
    m.t = 0;
    m.f.setZero();
    m.w.setZero();
    m.b.setZero();
    for (std::size_t j = 0; j < per_reading; ++j) {
      m.t += fine[k + j].t / static_cast<double>(per_reading);
      m.f += fine[k + j].f / static_cast<double>(per_reading);
      m.w += fine[k + j].w / static_cast<double>(per_reading);
      m.b += fine[k + j].b / static_cast<double>(per_reading);
    }
    means.push_back(m);
  }
  return means;
}

// A scenario's samples and the truth beside them.
inline std::pair<std::vector<Sample>, std::vector<TruthSample>> simulate(const sim::DrillingScenario& scenario) {
  sim::DrillingSimulator simulator(scenario);
  std::vector<TruthSample> truth;
  std::vector<Sample> samples = simulator.run(&truth);
  return {std::move(samples), std::move(truth)};
}

// Parameters matching a scenario's sensors (what a user of that tool would set).
inline estimator::Parameters parameters_for(const sim::DrillingScenario& s) {
  estimator::Parameters p;
  char text[64];
  auto set = [&](const char* name, double v) {
    std::snprintf(text, sizeof text, "%.10g", v);
    p[name] = text;
  };
  set("latitude_deg", s.latitude_deg);
  // A survey crew enters the local gravity; the simulator's magnetometer has white noise only,
  // so the heading model error per stop is set near zero (the default 0.05 deg allows for
  // calibration and crustal-field errors of a real tool).
  set("gravity", s.g);
  set("mag_heading_sd_deg", 0.005);
  set("gyro_arw_deg_rt_h", std::max(s.grade.gyro_arw_deg_rt_h, 1e-4));
  set("accel_vrw_mps_rt_h", std::max(s.grade.accel_vrw_mps_rt_h, 1e-4));
  set("gyro_bias_dph", std::max(s.grade.gyro_bias_deg_h, 1e-3));
  set("accel_bias_mg", std::max(s.grade.accel_bias_mg, 1e-3));
  // The string's magnetization as the user would state it: the spread the simulator draws it from.
  set("mag_axial_bias_uT", s.magnetometer.axial_bias_sd_uT);
  return p;
}

// The angle between a row's tool axis and the truth's: the direction position needs, which a weak
// azimuth near vertical leaves well defined (an invalid azimuth counts as the truth's).
inline double axis_error_deg(const Estimate& e, const TruthSample& tr) {
  const auto axis = [](double inc_deg, double azi_deg) {
    const double i = inc_deg * kDeg, a = azi_deg * kDeg;
    return Eigen::Vector3d(std::sin(i) * std::cos(a), std::sin(i) * std::sin(a), std::cos(i));
  };
  const Eigen::Vector3d est = axis(e.inclination_deg, e.azimuth_valid ? e.azimuth_deg : tr.azimuth_deg);
  const Eigen::Vector3d truth = axis(tr.inclination_deg, tr.azimuth_deg);
  return std::atan2(est.cross(truth).norm(), est.dot(truth)) / kDeg;
}

// Runs the navigator over samples and scores its rows against the truth. A row is the truth's at
// its stamp times the rate, or, where the stamps are not the true instants (a logger's clock), at
// the true index of the sample that bears its stamp (truth_index_of_stamp).
inline RunMetrics score_drilling(const std::vector<Sample>& samples, const std::vector<TruthSample>& truth,
                                 double rate, double drilled_m, const estimator::Parameters& params,
                                 std::map<std::string, std::uint64_t>* counters = nullptr,
                                 const std::map<double, std::size_t>* truth_index_of_stamp = nullptr);

inline RunMetrics run_drilling(const sim::DrillingScenario& scenario, const estimator::Parameters& params,
                               bool use_depth = true, std::map<std::string, std::uint64_t>* counters = nullptr) {
  sim::DrillingSimulator simulator(scenario);
  std::vector<TruthSample> truth;
  std::vector<Sample> samples = simulator.run(&truth);
  if (!use_depth) {
    for (Sample& s : samples) s.flags &= ~flags::kHasDepth;
  }
  return score_drilling(samples, truth, scenario.sample_rate_hz, simulator.trajectory().drilled_length_m(), params,
                        counters);
}

inline RunMetrics score_drilling(const std::vector<Sample>& samples, const std::vector<TruthSample>& truth,
                                 double rate, double drilled_m, const estimator::Parameters& params,
                                 std::map<std::string, std::uint64_t>* counters,
                                 const std::map<double, std::size_t>* truth_index_of_stamp) {
  Navigator nav(parse_parameters(params));
  std::vector<Estimate> rows;
  for (const Sample& s : samples) nav.push(s, rows);
  nav.flush(rows);
  if (counters != nullptr) *counters = nav.counters();

  RunMetrics m;
  m.rows = rows.size();
  m.drilled_m = drilled_m;
  for (const Estimate& e : rows) {
    if (!e.valid || !e.navigation) continue;
    ++m.valid_rows;
    const auto k = truth_index_of_stamp != nullptr ? truth_index_of_stamp->at(e.t_end)
                                                   : static_cast<std::size_t>(std::llround(e.t_end * rate));
    const TruthSample& tr = truth[std::min(k, truth.size() - 1)];
    const double di = e.inclination_deg - tr.inclination_deg;
    const double da = wrap_deg_180(e.azimuth_deg - tr.azimuth_deg);
    const double dt = wrap_deg_180(e.gravity_toolface_deg - tr.toolface_deg);
    m.max_inc_err_deg = std::max(m.max_inc_err_deg, std::abs(di));
    m.max_axis_err_deg = std::max(m.max_axis_err_deg, axis_error_deg(e, tr));
    if (e.azimuth_valid) m.max_azi_err_deg = std::max(m.max_azi_err_deg, std::abs(da));
    if (e.toolface_valid) m.max_tf_err_deg = std::max(m.max_tf_err_deg, std::abs(dt));
    int angle = 0;
    for (auto [err, sd] : {std::pair{di, e.inclination_sd_deg}, std::pair{da, e.azimuth_sd_deg},
                           std::pair{dt, e.toolface_sd_deg}}) {
      ++angle;
      if (sd > 0) {
        const double z = err / sd;
        m.sum_z2_angle[angle - 1] += z * z;
        m.n_z_angle[angle - 1] += 1;
        m.sum_z2 += z * z;
        m.n_z += 1;
        if (std::abs(z) > 3) m.count_z_above_3 += 1;
      }
    }
    const auto& p = e.navigation->position_m;
    m.end_position_err_m = std::hypot(p[0] - tr.north_m, p[1] - tr.east_m, p[2] - tr.down_m);
    const double truth_p[3] = {tr.north_m, tr.east_m, tr.down_m};
    m.end_position_z2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      const double sd = e.navigation->position_sd_m[i];
      if (sd > 0) m.end_position_z2 += (p[i] - truth_p[i]) * (p[i] - truth_p[i]) / (sd * sd);
    }
    m.end_azi_err_deg = da;
    m.end_azi_sd_deg = e.azimuth_sd_deg;
  }
  return m;
}

inline RunMetrics run_drilling(const sim::ImuGrade& grade, double rate_hz, std::uint64_t seed, bool use_depth = true) {
  const auto scenario = sim::DrillingScenario::reference(grade, rate_hz, seed);
  return run_drilling(scenario, parameters_for(scenario), use_depth);
}

inline void print(const char* label, const RunMetrics& m) {
  std::printf("%-28s rows %zu/%zu  max err I %.3f A %.3f T %.3f deg  end pos %.3f m (%.2f %% of %.1f m)  RMS(z) %.2f (I %.2f A %.2f T %.2f)\n",
              label, m.valid_rows, m.rows, m.max_inc_err_deg, m.max_azi_err_deg, m.max_tf_err_deg,
              m.end_position_err_m, m.end_position_pct(), m.drilled_m, m.rms_z(), m.rms_z_angle(0), m.rms_z_angle(1),
              m.rms_z_angle(2));
}

}  // namespace plumb::strapdown::test
