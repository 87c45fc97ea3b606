// The named drilling runs (the navigator's 16-minute accuracy case, a stop-and-go survey run) and the checks of a
// scenario's sensor and environment parameters.
#include <cmath>
#include <stdexcept>
#include <string>

#include "drilling_detail.hpp"
#include "plumb/sim/drilling.hpp"
#include "scenario_checks.hpp"

namespace plumb::sim {
namespace {

constexpr Refusal require_drilling{"invalid drilling scenario"};

DrillingScenario with_sensors(const ImuGrade& grade, double rate_hz, std::uint64_t seed) {
  DrillingScenario s;
  s.grade = grade;
  s.sample_rate_hz = rate_hz;
  s.seed = seed;
  s.latitude_deg = 35;
  s.g = 9.80665;
  s.total_b = 50;
  s.dip_deg = 60;
  s.magnetometer.sigma_uT = 0.1;
  return s;
}

}  // namespace

DrillingScenario DrillingScenario::reference(const ImuGrade& grade, double rate_hz, std::uint64_t seed) {
  DrillingScenario s = with_sensors(grade, rate_hz, seed);
  s.tool_id = "drilling-reference";
  auto& p = s.plan;
  p.inclination_deg = 85;
  p.azimuth_deg = 30;
  p.toolface_deg = 20;
  p.alignment_s = 60;
  p.ramp_s = 5;
  // 8 m at 0.05 m/s plus the ramps is 165 s; with 60 s connections the run lasts 60 + 4 x 225 s.
  p.segments = {DrillSegment::drill(8, 0.05, 8, 0),         DrillSegment::stop(60),
                DrillSegment::rotary(8, 0.05, 30, -1, 0),   DrillSegment::stop(60),
                DrillSegment::drill(8, 0.05, 6, -10),       DrillSegment::stop(60),
                DrillSegment::rotary(8, 0.05, 30, 2, 3),    DrillSegment::stop(60)};
  return s;
}

DrillingScenario DrillingScenario::survey_stop_and_go(const ImuGrade& grade, double rate_hz, std::uint64_t seed) {
  DrillingScenario s = with_sensors(grade, rate_hz, seed);
  s.tool_id = "drilling-survey";
  auto& p = s.plan;
  p.inclination_deg = 45;
  p.azimuth_deg = 120;
  p.toolface_deg = 0;
  p.alignment_s = 60;
  p.ramp_s = 5;
  p.segments.clear();
  for (int k = 0; k < 6; ++k) {
    p.segments.push_back(DrillSegment::rotary(1.5, 0.05, 60, 3, 1));
    p.segments.push_back(DrillSegment::stop(30));
  }
  return s;
}

double DrillingScenario::duration_s() const { return DrillingTrajectory(plan).duration_s(); }

namespace detail {

void validate(const DrillingScenario& s, std::size_t stop_count) {
  validate_imu_site(s, require_drilling);
  require_drilling(finite_nonneg(s.magnetometer.sigma_uT), "magnetometer noise must be finite and >= 0 uT");
  require_drilling(finite_nonneg(s.magnetometer.axial_bias_sd_uT), "magnetometer axial bias spread must be finite and >= 0 uT");
  require_drilling(!s.magnetometer.axial_bias_uT || std::isfinite(*s.magnetometer.axial_bias_uT), "magnetometer axial bias must be finite");
  for (const auto& d : s.magnetometer.disturbances) {
    require_drilling(d.stop_index < stop_count, "magnetic disturbance at stop " + std::to_string(d.stop_index) +
                                           " but the plan has " + std::to_string(stop_count) + " stop(s) (0-based)");
    require_drilling(std::isfinite(d.delta_total_uT) && std::isfinite(d.delta_dip_deg),
            "magnetic disturbance offsets must be finite");
    require_drilling(s.total_b + d.delta_total_uT >= 0 && std::abs(s.dip_deg + d.delta_dip_deg) <= 90,
            "a disturbed field must keep |B| >= 0 and dip within [-90, 90] deg");
  }
  require_drilling(finite_nonneg(s.depth.sigma_m) && finite_nonneg(s.depth.quantum_m), "depth noise and quantum must be >= 0 m");
  require_drilling(finite_nonneg(s.depth.heave_amplitude_m) && std::isfinite(s.depth.heave_period_s) &&
                       s.depth.heave_period_s > 0,
                   "heave amplitude must be >= 0 m and its period > 0 s");
  const auto& v = s.vibration;
  const std::string vibration = vibration_problem(v);
  require_drilling(vibration.empty(), vibration);
  require_drilling(finite_nonneg(v.shock_rate_hz), "shock rate must be >= 0 Hz");
  require_drilling(std::isfinite(v.shock_peak) && std::isfinite(v.shock_duration_s) && v.shock_duration_s > 0,
          "shock peak and duration must be finite, duration > 0");
  require_drilling(s.tool_id.size() <= 31, "tool id: at most 31 characters");
  const ToolTemperature& temp = s.temperature;
  require_drilling(std::isfinite(temp.circulating_c) && std::isfinite(temp.formation_c) && std::isfinite(temp.start_c),
                   "tool temperatures must be finite");
  require_drilling(std::isfinite(temp.heat_tau_s) && temp.heat_tau_s > 0 && std::isfinite(temp.cool_tau_s) &&
                       temp.cool_tau_s > 0,
                   "tool temperature time constants must be > 0 s");
  require_drilling(finite_nonneg(temp.sensor_sigma_c) && finite_nonneg(temp.sensor_quantum_c),
                   "temperature sensor noise and step must be >= 0 degC");
  require_drilling(std::isfinite(s.grade.gyro_bias_temp_dph_per_c) && std::isfinite(s.grade.accel_bias_temp_mg_per_c),
                   "IMU grade '" + s.grade.name + "': temperature coefficients must be finite");
}

}  // namespace detail
}  // namespace plumb::sim
