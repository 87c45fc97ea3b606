// Drilling runs through a navigator plugin, scored against the simulator's exact trajectory.
#include <algorithm>
#include <cmath>

#include "plumb/compare/drilling.hpp"
#include "plumb/core/attitude.hpp"
#include "plumb/estimator/loader.hpp"
#include "plumb/sim/drilling.hpp"

namespace plumb::compare {
namespace {

struct Sums {
  double inc2 = 0, azi2 = 0, tf2 = 0, att_cov = 0, pos_cov = 0;
  int att_n = 0, pos_n = 0, n = 0;
  double angle_cov[3] = {};  // inclination, azimuth, toolface
  int angle_n[3] = {};
};

double ratio2(double err, double sd) { return sd > 0 ? (err / sd) * (err / sd) : 0; }

void score(const Estimate& e, const sim::DrillingTrajectory& truth, DrillingRunResult& r, Sums& s) {
  ++r.estimates;
  if (!e.valid || !e.navigation) {
    if (r.first_invalid_reason.empty()) r.first_invalid_reason = e.reason;
    return;
  }
  ++r.valid;
  const sim::DrillingState x = truth.at(e.t_end);
  ErrorPoint p;
  p.t = e.t_end;
  p.inclination_deg = e.inclination_deg - x.inclination / kDeg;
  p.azimuth_deg = e.azimuth_valid ? wrap_deg_180(e.azimuth_deg - x.azimuth / kDeg) : 0;
  p.toolface_deg = e.toolface_valid ? wrap_deg_180(e.gravity_toolface_deg - x.toolface / kDeg) : 0;
  const auto& nav = *e.navigation;
  p.north_m = nav.position_m[0] - x.position.x();
  p.east_m = nav.position_m[1] - x.position.y();
  p.down_m = nav.position_m[2] - x.position.z();
  r.errors.push_back(p);

  r.max_inclination_deg = std::max(r.max_inclination_deg, std::abs(p.inclination_deg));
  r.max_azimuth_deg = std::max(r.max_azimuth_deg, std::abs(p.azimuth_deg));
  r.max_toolface_deg = std::max(r.max_toolface_deg, std::abs(p.toolface_deg));
  s.inc2 += p.inclination_deg * p.inclination_deg;
  s.azi2 += p.azimuth_deg * p.azimuth_deg;
  s.tf2 += p.toolface_deg * p.toolface_deg;
  ++s.n;
  const double dvn = nav.velocity_mps[0] - x.velocity.x(), dve = nav.velocity_mps[1] - x.velocity.y();
  r.max_horizontal_velocity_mps = std::max(r.max_horizontal_velocity_mps, std::hypot(dvn, dve));
  r.max_down_velocity_mps = std::max(r.max_down_velocity_mps, std::abs(nav.velocity_mps[2] - x.velocity.z()));
  const std::pair<double, double> angles[3] = {{p.inclination_deg, e.inclination_sd_deg},
                                               {p.azimuth_deg, e.azimuth_valid ? e.azimuth_sd_deg : 0.0},
                                               {p.toolface_deg, e.toolface_valid ? e.toolface_sd_deg : 0.0}};
  for (int i = 0; i < 3; ++i) {
    const auto [err, sd] = angles[i];
    if (sd > 0) s.att_cov += ratio2(err, sd), ++s.att_n, s.angle_cov[i] += ratio2(err, sd), ++s.angle_n[i];
  }
  const double pos_err[3] = {p.north_m, p.east_m, p.down_m};
  for (int i = 0; i < 3; ++i)
    if (nav.position_sd_m[static_cast<std::size_t>(i)] > 0)
      s.pos_cov += ratio2(pos_err[i], nav.position_sd_m[static_cast<std::size_t>(i)]), ++s.pos_n;
  r.end_position_m = std::sqrt(p.north_m * p.north_m + p.east_m * p.east_m + p.down_m * p.down_m);
}

}  // namespace

std::vector<DrillingRunResult> run_drilling_compare(const DrillingCompareConfig& config) {
  if (config.seeds < 1) throw std::invalid_argument("seeds must be at least 1");
  estimator::Runner runner = estimator::load_runner({config.plugin});
  runner.configure(config.assignments, std::nullopt);  // validates before any run
  std::vector<DrillingRunResult> runs;
  std::uint64_t serial = 0;
  for (const auto& grade : config.grades) {
    for (double rate : config.rates_hz) {
      for (bool depth : config.with_depth) {
        for (int k = 0; k < config.seeds; ++k, ++serial) {
          auto scenario = sim::DrillingScenario::reference(sim::ImuGrade::named(grade), rate, config.base_seed + serial);
          scenario.depth.present = depth;
          scenario.magnetometer.present = config.magnetometer;
          sim::DrillingSimulator simulator(scenario);
          DrillingRunResult r;
          r.grade = grade, r.rate_hz = rate, r.with_depth = depth, r.seed = scenario.seed;
          r.drilled_m = simulator.trajectory().drilled_length_m();
          Sums sums;
          const auto sink = [&](const estimator::Runner::Slot&, Estimate& e) { score(e, simulator.trajectory(), r, sums); };
          // What the operator of a real run knows: the site's latitude and gravity, the tool's
          // IMU grade and how magnetic the string is (the spread the simulator draws it from). The
          // user's own --param come last and win.
          std::vector<std::string> assignments{
              "latitude_deg=" + std::to_string(scenario.latitude_deg), "gravity=" + std::to_string(scenario.g),
              "imu_grade=" + grade, "mag_axial_bias_uT=" + std::to_string(scenario.magnetometer.axial_bias_sd_uT)};
          assignments.insert(assignments.end(), config.assignments.begin(), config.assignments.end());
          runner.configure(assignments, std::nullopt);
          std::vector<Sample> chunk;
          while (!simulator.done()) {
            chunk.push_back(simulator.next());
            if (chunk.size() == 4096 || simulator.done()) {
              runner.push(chunk, sink);
              chunk.clear();
            }
          }
          runner.flush(sink);
          if (sums.n > 0) {
            r.rms_inclination_deg = std::sqrt(sums.inc2 / sums.n);
            r.rms_azimuth_deg = std::sqrt(sums.azi2 / sums.n);
            r.rms_toolface_deg = std::sqrt(sums.tf2 / sums.n);
          }
          r.attitude_coverage = sums.att_n > 0 ? std::sqrt(sums.att_cov / sums.att_n) : 0;
          r.position_coverage = sums.pos_n > 0 ? std::sqrt(sums.pos_cov / sums.pos_n) : 0;
          double* per_angle[3] = {&r.inclination_coverage, &r.azimuth_coverage, &r.toolface_coverage};
          for (int i = 0; i < 3; ++i) *per_angle[i] = sums.angle_n[i] > 0 ? std::sqrt(sums.angle_cov[i] / sums.angle_n[i]) : 0;
          r.max_attitude_deg = std::max({r.max_inclination_deg, r.max_azimuth_deg, r.max_toolface_deg});
          runs.push_back(std::move(r));
        }
      }
    }
  }
  return runs;
}

}  // namespace plumb::compare
