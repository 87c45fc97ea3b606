// The grid runner: simulate each record once, feed it to every plugin, accumulate errors.
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "plumb/compare/compare.hpp"
#include "plumb/core/attitude.hpp"
#include "plumb/estimator/loader.hpp"
#include "plumb/windowed/cramer_rao.hpp"

namespace plumb::compare {

std::vector<double> CompareConfig::azimuth_sweep() const {
  if (!azimuths_deg.empty()) return azimuths_deg;
  std::vector<double> sweep;
  for (int a = 0; a < 360; a += 10) sweep.push_back(a);
  return sweep;
}

CompareConfig CompareConfig::single(const sim::Scenario& scenario, int seeds) {
  CompareConfig c;
  c.base = scenario;
  c.inclinations_deg = {scenario.inclination_deg};
  c.azimuths_deg = {scenario.azimuth_deg};
  c.rpms = {scenario.rotation.kind == sim::ProfileKind::Ramp ? scenario.rotation.rpm_end : scenario.rotation.rpm};
  c.snr_accel_db = {scenario.noise.snr_accel_db.value_or(0)};
  c.snr_mag_db = scenario.noise.snr_mag_db.value_or(0);
  c.use_base_noise = true;
  c.vary_toolface = false;
  c.seeds = seeds;
  c.base_seed = scenario.seed;
  return c;
}

const PluginCaseResult* CaseResult::find(const std::string& plugin) const {
  for (const auto& p : plugins) {
    if (p.plugin == plugin) return &p;
  }
  return nullptr;
}

namespace {

struct Accumulator {
  double sum_az = 0, sum_az2 = 0, sum_inc = 0, sum_inc2 = 0, sum_sd2 = 0;
  double max_az = 0, max_inc = 0;
  double az_z2 = 0, inc_z2 = 0;  // squared error / reported sd
  int valid = 0, valid_inc = 0, records = 0, az_z = 0, inc_z = 0;

  void add(const Estimate& e, double inc_true, double az_true) {
    ++records;
    if (e.valid) {
      const double di = e.inclination_deg - inc_true;
      sum_inc += di, sum_inc2 += di * di, ++valid_inc;
      max_inc = std::max(max_inc, std::abs(di));
      if (e.inclination_sd_deg > 0) inc_z2 += (di / e.inclination_sd_deg) * (di / e.inclination_sd_deg), ++inc_z;
    }
    if (e.valid && e.azimuth_valid) {
      const double da = wrap_deg_180(e.azimuth_deg - az_true);
      sum_az += da, sum_az2 += da * da, ++valid;
      max_az = std::max(max_az, std::abs(da));
      if (std::isfinite(e.azimuth_sd_deg)) sum_sd2 += e.azimuth_sd_deg * e.azimuth_sd_deg;  // NaN: not estimated
      if (e.azimuth_sd_deg > 0) az_z2 += (da / e.azimuth_sd_deg) * (da / e.azimuth_sd_deg), ++az_z;
    }
  }
  void merge(const Accumulator& o) {
    sum_az += o.sum_az, sum_az2 += o.sum_az2, sum_inc += o.sum_inc, sum_inc2 += o.sum_inc2, sum_sd2 += o.sum_sd2;
    max_az = std::max(max_az, o.max_az), max_inc = std::max(max_inc, o.max_inc);
    valid += o.valid, valid_inc += o.valid_inc, records += o.records;
    az_z2 += o.az_z2, inc_z2 += o.inc_z2, az_z += o.az_z, inc_z += o.inc_z;
  }
};

double safe_div(double a, int n) { return n > 0 ? a / n : 0.0; }

sim::Scenario record_scenario(const CompareConfig& config, double inc, double az, double rpm, double snr,
                              std::uint64_t seed, std::uint64_t serial) {
  sim::Scenario s = config.base;
  s.inclination_deg = inc;
  s.azimuth_deg = az;
  if (s.rotation.kind == sim::ProfileKind::Ramp) {
    s.rotation.rpm_end = rpm;
  } else {
    s.rotation.rpm = rpm;
  }
  if (!config.use_base_noise) {
    s.noise.sigma_accel.reset();
    s.noise.sigma_mag.reset();
    s.noise.snr_accel_db = snr;
    s.noise.snr_mag_db = config.snr_mag_db;
  }
  s.seed = seed;
  // Golden-angle steps spread the start toolface evenly whatever the number of records.
  if (config.vary_toolface) s.toolface0_deg = std::fmod(137.50776405 * static_cast<double>(serial), 360.0);
  return s;
}

windowed::CrbCase crb_case(const sim::Scenario& s, double rpm) {
  windowed::CrbCase c;
  c.g = s.g;
  c.total_b = s.total_b;
  c.dip_deg = s.dip_deg;
  c.inclination_deg = s.inclination_deg;
  c.azimuth_deg = s.azimuth_deg;
  c.toolface0_deg = 0;
  c.rpm = rpm;
  c.sigma_accel = s.sigma_accel();
  c.sigma_mag = s.sigma_mag();
  c.sample_rate_hz = s.sample_rate_hz;
  c.duration_s = s.duration_s;
  return c;
}

// Fits the mean error per azimuth to a + b sinA + c cosA.
void fit_bias(PluginCaseResult& p) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d y = Eigen::Vector3d::Zero();
  int used = 0;
  for (const auto& pt : p.by_azimuth) {
    if (pt.valid == 0) continue;
    const Eigen::Vector3d row(1, std::sin(pt.azimuth_deg * kDeg), std::cos(pt.azimuth_deg * kDeg));
    a += row * row.transpose();
    y += row * pt.mean_azimuth_error_deg;
    ++used;
  }
  if (used < 3) return;
  const Eigen::Vector3d c = a.ldlt().solve(y);
  p.bias_mean_deg = c[0], p.bias_sin_deg = c[1], p.bias_cos_deg = c[2];
}

}  // namespace

CompareResult run_compare(const CompareConfig& config, const ProgressCallback& progress) {
  const auto started = std::chrono::steady_clock::now();
  if (config.plugins.empty()) throw std::runtime_error("no estimator plugins chosen");
  if (config.seeds < 1) throw std::runtime_error("seeds must be at least 1");
  estimator::Runner runner = estimator::load_runner(config.plugins);
  runner.configure(config.assignments, 0.0);  // validates now, before any long run
  const std::size_t plugin_count = runner.slots().size();
  const std::vector<double> azimuths = config.azimuth_sweep();
  const std::size_t total = config.inclinations_deg.size() * config.rpms.size() * config.snr_accel_db.size() *
                            azimuths.size() * static_cast<std::size_t>(config.seeds);
  CompareResult result;
  result.plugins = config.plugins;
  std::size_t done = 0, case_index = 0;
  std::vector<Sample> samples;
  for (double inc : config.inclinations_deg) {
    for (double rpm : config.rpms) {
      for (double snr : config.snr_accel_db) {
        CaseResult cr;
        cr.inclination_deg = inc, cr.rpm = rpm, cr.snr_accel_db = snr, cr.snr_mag_db = config.snr_mag_db;
        std::vector<Accumulator> totals(plugin_count);
        std::vector<PluginCaseResult> plugin_results(plugin_count);
        std::vector<std::string> first_reason(plugin_count);
        double crb_az2 = 0, crb_inc2 = 0;
        for (std::size_t ai = 0; ai < azimuths.size(); ++ai) {
          const double az = azimuths[ai];
          std::vector<Accumulator> here(plugin_count);
          sim::Scenario first;
          for (int seed = 0; seed < config.seeds; ++seed) {
            const std::uint64_t serial = (case_index * azimuths.size() + ai) * static_cast<std::uint64_t>(config.seeds) +
                                         static_cast<std::uint64_t>(seed);
            const sim::Scenario s = record_scenario(config, inc, az, rpm, snr, config.base_seed + serial, serial);
            if (seed == 0) first = s;
            sim::PlatformSimulator simulator(s);
            samples = simulator.run();
            runner.reset();
            const auto tally = [&](const estimator::Runner::Slot& slot, Estimate& e) {
              const auto p = static_cast<std::size_t>(&slot - runner.slots().data());
              here[p].add(e, inc, az);
              if ((!e.valid || !e.azimuth_valid) && first_reason[p].empty()) first_reason[p] = e.reason;
            };
            runner.push(samples, tally);
            runner.flush(tally);
            ++done;
            if (progress) progress(done, total);
          }
          const windowed::CrbResult crb = windowed::cramer_rao_bound(crb_case(first, rpm));
          crb_az2 += crb.azimuth_deg * crb.azimuth_deg;
          crb_inc2 += crb.inclination_deg * crb.inclination_deg;
          if (ai == 0) {
            cr.sigma_accel = first.sigma_accel();
            cr.sigma_mag = first.sigma_mag();
          }
          for (std::size_t p = 0; p < plugin_count; ++p) {
            AzimuthPoint pt;
            pt.azimuth_deg = az;
            pt.mean_azimuth_error_deg = safe_div(here[p].sum_az, here[p].valid);
            pt.mean_inclination_error_deg = safe_div(here[p].sum_inc, here[p].valid_inc);
            pt.rms_azimuth_error_deg = std::sqrt(safe_div(here[p].sum_az2, here[p].valid));
            pt.rms_inclination_error_deg = std::sqrt(safe_div(here[p].sum_inc2, here[p].valid_inc));
            pt.crb_azimuth_deg = crb.azimuth_deg;
            pt.crb_inclination_deg = crb.inclination_deg;
            pt.valid = here[p].valid;
            pt.records = here[p].records;
            plugin_results[p].by_azimuth.push_back(pt);
            totals[p].merge(here[p]);
          }
        }
        const int n_az = static_cast<int>(azimuths.size());
        cr.crb_azimuth_deg = std::sqrt(safe_div(crb_az2, n_az));
        cr.crb_inclination_deg = std::sqrt(safe_div(crb_inc2, n_az));
        for (std::size_t p = 0; p < plugin_count; ++p) {
          PluginCaseResult& pr = plugin_results[p];
          const Accumulator& t = totals[p];
          pr.plugin = config.plugins[p];
          pr.rms_azimuth_error_deg = std::sqrt(safe_div(t.sum_az2, t.valid));
          pr.max_azimuth_error_deg = t.max_az;
          pr.rms_inclination_error_deg = std::sqrt(safe_div(t.sum_inc2, t.valid_inc));
          pr.max_inclination_error_deg = t.max_inc;
          pr.mean_azimuth_sd_deg = std::sqrt(safe_div(t.sum_sd2, t.valid));
          pr.azimuth_coverage = std::sqrt(safe_div(t.az_z2, t.az_z));
          pr.inclination_coverage = std::sqrt(safe_div(t.inc_z2, t.inc_z));
          pr.valid = t.valid;
          pr.records = t.records;
          pr.first_invalid_reason = first_reason[p];
          fit_bias(pr);
          cr.plugins.push_back(std::move(pr));
        }
        result.cases.push_back(std::move(cr));
        ++case_index;
      }
    }
  }
  result.records = done;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace plumb::compare
