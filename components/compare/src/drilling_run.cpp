// Drilling runs through a navigator plugin, scored against the simulator's exact trajectory.
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "plumb/compare/drilling.hpp"
#include "plumb/core/attitude.hpp"
#include "plumb/estimator/loader.hpp"
#include "plumb/sim/drilling.hpp"
#include "plumb/sim/rig_depth.hpp"

namespace plumb::compare {
namespace {

struct Sums {
  double inc2 = 0, azi2 = 0, tf2 = 0, att_cov = 0, pos_cov = 0;
  int att_n = 0, pos_n = 0, n = 0;
  double end_pos_cov = 0;  // the last valid row's, over N, E, D
  int end_pos_n = 0;
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
  s.end_pos_cov = 0, s.end_pos_n = 0;
  for (int i = 0; i < 3; ++i)
    if (const double sd = nav.position_sd_m[static_cast<std::size_t>(i)]; sd > 0) {
      s.pos_cov += ratio2(pos_err[i], sd), ++s.pos_n;
      s.end_pos_cov += ratio2(pos_err[i], sd), ++s.end_pos_n;
    }
  r.end_position_m = std::sqrt(p.north_m * p.north_m + p.east_m * p.east_m + p.down_m * p.down_m);
}

// The lengths drilled from one stop to the next, the alignment's stop first: the pipe tally of the
// joints run in at each connection, as the driller measured them (to sd_m).
std::string measured_tally(const sim::DrillingTrajectory& trajectory, double sd_m, std::uint64_t seed) {
  std::vector<double> joints;
  bool moving = false;
  for (const auto& phase : trajectory.phases()) {
    if (phase.moving && !moving) joints.push_back(0);
    if (phase.moving) joints.back() += trajectory.at(phase.t1).depth_m - phase.s0;
    moving = phase.moving;
  }
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> error(0.0, 1.0);
  std::string list;
  for (double joint : joints) list += (list.empty() ? "" : ",") + std::to_string(joint + sd_m * error(rng));
  return list;
}

// The reference run of one grade and rate, its sensors and depth as the family has them.
sim::DrillingScenario scenario_for(const DrillingCompareConfig& config, const std::string& grade, double rate,
                                   DepthFamily family, std::uint64_t seed) {
  auto scenario = sim::DrillingScenario::reference(sim::ImuGrade::named(grade), rate, seed);
  scenario.grade.gyro_arw_deg_rt_h *= config.noisier;
  scenario.grade.accel_vrw_mps_rt_h *= config.noisier;
  scenario.depth.present = family == DepthFamily::sensor || family == DepthFamily::rig;
  // The rig family starts from the exact depth and adds its own noise to each report.
  scenario.depth.sigma_m = family == DepthFamily::sensor ? config.depth_sd_m : 0;
  scenario.magnetometer.present = config.magnetometer;
  return scenario;
}

// What the operator of a real run knows: the site's latitude and gravity, the tool's IMU grade
// (not how much noisier this tool is than its grade), how magnetic the string is (the spread the
// simulator draws it from) and, with a tally, the joints run in. The user's own --param come last
// and win.
std::vector<std::string> assignments_for(const DrillingCompareConfig& config, const sim::DrillingScenario& scenario,
                                         const std::string& grade, DepthFamily family,
                                         const sim::DrillingTrajectory& trajectory) {
  std::vector<std::string> a{"latitude_deg=" + std::to_string(scenario.latitude_deg), "gravity=" + std::to_string(scenario.g),
                             "imu_grade=" + grade,
                             "mag_axial_bias_uT=" + std::to_string(scenario.magnetometer.axial_bias_sd_uT)};
  if (family == DepthFamily::tally) {
    a.push_back("pipe_tally_m=" + measured_tally(trajectory, config.tally_sd_m, scenario.seed));
    a.push_back("pipe_tally_sd_m=" + std::to_string(config.tally_sd_m));
  }
  a.insert(a.end(), config.assignments.begin(), config.assignments.end());
  return a;
}

void finish(DrillingRunResult& r, const Sums& sums) {
  if (sums.n > 0) {
    r.rms_inclination_deg = std::sqrt(sums.inc2 / sums.n);
    r.rms_azimuth_deg = std::sqrt(sums.azi2 / sums.n);
    r.rms_toolface_deg = std::sqrt(sums.tf2 / sums.n);
  }
  r.attitude_coverage = sums.att_n > 0 ? std::sqrt(sums.att_cov / sums.att_n) : 0;
  r.attitude_ratios = sums.att_n;
  r.position_coverage = sums.pos_n > 0 ? std::sqrt(sums.pos_cov / sums.pos_n) : 0;
  r.end_position_coverage = sums.end_pos_n > 0 ? std::sqrt(sums.end_pos_cov / sums.end_pos_n) : 0;
  double* per_angle[3] = {&r.inclination_coverage, &r.azimuth_coverage, &r.toolface_coverage};
  for (int i = 0; i < 3; ++i) *per_angle[i] = sums.angle_n[i] > 0 ? std::sqrt(sums.angle_cov[i] / sums.angle_n[i]) : 0;
  r.max_attitude_deg = std::max({r.max_inclination_deg, r.max_azimuth_deg, r.max_toolface_deg});
}

DrillingRunResult run_one(const DrillingCompareConfig& config, estimator::Runner& runner, const std::string& grade,
                          double rate, DepthFamily family, std::uint64_t seed) {
  const auto scenario = scenario_for(config, grade, rate, family, seed);
  sim::DrillingSimulator simulator(scenario);
  DrillingRunResult r;
  r.grade = grade, r.rate_hz = rate, r.family = family, r.seed = scenario.seed;
  r.drilled_m = simulator.trajectory().drilled_length_m();
  Sums sums;
  const auto sink = [&](const estimator::Runner::Slot&, Estimate& e) { score(e, simulator.trajectory(), r, sums); };
  runner.configure(assignments_for(config, scenario, grade, family, simulator.trajectory()), std::nullopt);
  auto rig = config.rig;
  rig.sd_m = config.depth_sd_m;
  sim::RigDepthReporter reporter(rig, rate, scenario.seed + 1000003);  // its noise apart from the sensors'
  std::vector<Sample> chunk;
  while (!simulator.done()) {
    chunk.push_back(simulator.next());
    if (family == DepthFamily::rig) reporter.apply(chunk.back());
    if (chunk.size() == 4096 || simulator.done()) {
      runner.push(chunk, sink);
      chunk.clear();
    }
  }
  runner.flush(sink);
  finish(r, sums);
  return r;
}

}  // namespace

const char* family_name(DepthFamily family) {
  switch (family) {
    case DepthFamily::sensor: return "yes";
    case DepthFamily::none: return "no";
    case DepthFamily::rig: return "rig";
    case DepthFamily::tally: return "tally";
  }
  return "?";
}

const char* family_label(DepthFamily family) {
  switch (family) {
    case DepthFamily::sensor: return "depth";
    case DepthFamily::none: return "no depth";
    case DepthFamily::rig: return "rig depth";
    case DepthFamily::tally: return "pipe tally";
  }
  return "?";
}

std::vector<DrillingRunResult> run_drilling_compare(const DrillingCompareConfig& config,
                                                    const std::function<void(std::size_t, std::size_t)>& progress) {
  if (config.seeds < 1) throw std::invalid_argument("seeds must be at least 1");
  if (!(std::isfinite(config.noisier) && config.noisier > 0)) throw std::invalid_argument("the noise multiplier must be > 0");
  if (!(std::isfinite(config.depth_sd_m) && config.depth_sd_m >= 0)) throw std::invalid_argument("the depth noise must be >= 0 m");
  if (!(std::isfinite(config.tally_sd_m) && config.tally_sd_m >= 0)) throw std::invalid_argument("the tally's sd must be >= 0 m");
  if (std::find(config.families.begin(), config.families.end(), DepthFamily::rig) != config.families.end()) {
    auto rig = config.rig;
    rig.sd_m = config.depth_sd_m;
    for (double rate : config.rates_hz) sim::RigDepthReporter(rig, rate, 0);  // validates before any run
  }
  estimator::Runner runner = estimator::load_runner({config.plugin});
  runner.configure(config.assignments, std::nullopt);  // validates before any run
  std::vector<DrillingRunResult> runs;
  const std::size_t total = config.grades.size() * config.rates_hz.size() * config.families.size() *
                            static_cast<std::size_t>(config.seeds);
  if (progress) progress(0, total);
  std::uint64_t serial = 0;
  for (const auto& grade : config.grades)
    for (double rate : config.rates_hz)
      for (DepthFamily family : config.families)
        for (int k = 0; k < config.seeds; ++k, ++serial) {
          runs.push_back(run_one(config, runner, grade, rate, family, config.base_seed + serial));
          if (progress) progress(runs.size(), total);
        }
  return runs;
}

}  // namespace plumb::compare
