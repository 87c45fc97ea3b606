// plumb compare: estimator plugins side by side on simulated scenarios, beside the Cramér–Rao bound.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "compare/compare_file.hpp"
#include "messages/fields.hpp"
#include "plots/plot_runner.hpp"
#include "plumb/compare/compare.hpp"
#include "plumb/compare/drilling.hpp"
#include "plumb/components/cli.hpp"
#include "verbs.hpp"

namespace plumb::cli {
namespace {

struct CompareOptions {
  std::vector<std::string> estimators{"static", "integral", "compensated"};
  std::vector<double> inclinations{0.5, 1, 2};
  std::vector<double> rpms{0, 60, 120};
  std::vector<double> snr_accel{10, 20};
  double snr_mag = 20;
  std::vector<double> azimuths;
  int seeds = 4;
  std::uint64_t seed = 1;
  std::string profile;
  double duration_s = 10;
  double rate_hz = 100;
  double g = 10, field = 48.4, dip = 45.5;
  std::string accel_bias, mag_bias;
  std::vector<std::string> params;
  std::string plots_dir;
  std::string csv_path;
  std::string scenario = "platform";
  std::vector<std::string> grades{"tactical", "mems"};
  std::vector<double> drilling_rates{100, 10};
  std::vector<std::string> depth{"both"};
  double depth_sd_m = 0;
  double rig_interval_s = 1, rig_quantum_m = 0.01, rig_late_s = 1;
  bool rig_empty = false;
  double tally_sd_m = 0.02;
  double noisier = 1;
  bool no_magnetometer = false;
};

// The drilling scenario's options that only a family given with --depth uses.
const char* const kRigOptions[] = {"--rig-interval", "--rig-quantum", "--rig-late", "--rig-empty"};
const char* const kDrillingOnlyOptions[] = {"--grade", "--drilling-rate-hz", "--depth", "--depth-sd", "--rig-interval",
                                            "--rig-quantum", "--rig-late", "--rig-empty", "--tally-sd", "--noisier",
                                            "--no-magnetometer"};

Eigen::Vector3d parse_vector(const std::string& text, const std::string& option) {
  const auto parts = split(text, ',');
  if (parts.size() != 3) throw std::invalid_argument(option + " takes x,y,z");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) parse_scalar(parts[static_cast<std::size_t>(i)], v[i], option);
  return v;
}

// Progress on stderr: a redrawn bar on a terminal, a line every 10% otherwise (logs, CI).
compare::ProgressCallback progress_printer(const std::string& unit) {
  const bool tty = isatty(STDERR_FILENO);
  auto last_decile = std::make_shared<int>(-1);
  return [tty, last_decile, unit](std::size_t done, std::size_t total) {
    const int percent = total ? static_cast<int>(100 * done / total) : 100;
    if (tty) {
      const int filled = percent / 4;
      std::cerr << "\r[" << std::string(static_cast<std::size_t>(filled), '#') << std::string(static_cast<std::size_t>(25 - filled), ' ')
                << "] " << percent << "% (" << done << "/" << total << " " << unit << ")" << (done == total ? "\n" : "") << std::flush;
    } else if (percent / 10 != *last_decile) {
      *last_decile = percent / 10;
      std::cerr << "plumb compare: " << percent << "% (" << done << "/" << total << " " << unit << ")" << std::endl;
    }
  };
}

// --depth's words, in the order given, each family once.
std::vector<compare::DepthFamily> depth_families(const std::vector<std::string>& words) {
  using F = compare::DepthFamily;
  std::vector<F> families;
  const auto add = [&](std::initializer_list<F> fs) {
    for (F f : fs)
      if (std::find(families.begin(), families.end(), f) == families.end()) families.push_back(f);
  };
  for (const auto& w : words) {
    if (w == "yes") add({F::sensor});
    else if (w == "no") add({F::none});
    else if (w == "both") add({F::sensor, F::none});
    else if (w == "rig") add({F::rig});
    else if (w == "tally") add({F::tally});
    else if (w == "all") add({F::sensor, F::none, F::rig, F::tally});
    else throw std::invalid_argument("--depth takes yes, no, both, rig, tally or all, not '" + w + "'");
  }
  return families;
}

void require_within(double value, double low, double high, const std::string& what) {
  if (!(value >= low && value <= high)) {  // NaN fails too
    char text[160];
    std::snprintf(text, sizeof text, "%s must be between %g and %g", what.c_str(), low, high);
    throw std::invalid_argument(text);
  }
}

// The families' figures, each refused when out of range or given for a family not run.
void set_family_figures(const CompareOptions& o, const CLI::App& cmd, compare::DrillingCompareConfig& c) {
  using F = compare::DepthFamily;
  const auto runs = [&](F f) { return std::find(c.families.begin(), c.families.end(), f) != c.families.end(); };
  const auto given = [&](const char* option) { return cmd.get_option(option)->count() > 0; };
  if (given("--depth-sd") && !runs(F::sensor) && !runs(F::rig))
    throw std::invalid_argument("--depth-sd is the depth sensor's noise: it applies to --depth yes, both, rig or all");
  for (const char* option : kRigOptions)
    if (given(option) && !runs(F::rig)) throw std::invalid_argument(std::string(option) + " applies to --depth rig (or all)");
  if (given("--tally-sd") && !runs(F::tally)) throw std::invalid_argument("--tally-sd applies to --depth tally (or all)");
  require_within(o.depth_sd_m, 0, 1, "--depth-sd (m)");
  // At least one row of the slowest rate between reports.
  const double slowest_hz = o.drilling_rates.empty() ? 1 : *std::min_element(o.drilling_rates.begin(), o.drilling_rates.end());
  require_within(o.rig_interval_s, slowest_hz > 0 ? 1 / slowest_hz : 0, 600, "--rig-interval (s)");
  require_within(o.rig_quantum_m, 0, 1, "--rig-quantum (m)");
  require_within(o.rig_late_s, 0, 60, "--rig-late (s)");
  require_within(o.tally_sd_m, 0, 1, "--tally-sd (m)");
  if (!(o.noisier > 0 && o.noisier <= 1000)) throw std::invalid_argument("--noisier must be above 0 and at most 1000");
  c.depth_sd_m = o.depth_sd_m;
  c.rig.interval_s = o.rig_interval_s;
  c.rig.quantum_m = o.rig_quantum_m;
  c.rig.late_s = o.rig_late_s;
  c.rig.empty_between = o.rig_empty;
  c.tally_sd_m = o.tally_sd_m;
  c.noisier = o.noisier;
}

// The navigator on the simulator's drilling runs: per run, errors beside the source's figures.
int run_drilling(const CompareOptions& o, const CLI::App& cmd, bool estimators_given) {
  compare::DrillingCompareConfig c;
  if (estimators_given) {
    if (o.estimators.size() != 1) throw std::invalid_argument("--scenario drilling takes one --estimator (a navigator)");
    c.plugin = o.estimators.front();
  }
  c.grades = o.grades;
  c.rates_hz = o.drilling_rates;
  c.families = depth_families(o.depth);
  set_family_figures(o, cmd, c);
  c.magnetometer = !o.no_magnetometer;
  if (o.seeds < 1) throw std::invalid_argument("--seeds must be at least 1");
  c.seeds = o.seeds;
  c.base_seed = o.seed;
  c.assignments = o.params;
  const auto runs = compare::run_drilling_compare(c, progress_printer("drilling runs"));
  compare::write_drilling_report(std::cout, runs, c);
  if (!o.plots_dir.empty()) {
    std::filesystem::create_directories(o.plots_dir);
    const std::string path = (std::filesystem::path(o.plots_dir) / "drilling_errors.csv").string();
    {
      std::ofstream f(path);
      if (!f) throw std::runtime_error("cannot write '" + path + "'");
      compare::write_drilling_errors_csv(f, runs);
    }
    run_plot("drilling", path, (std::filesystem::path(o.plots_dir) / "drilling_errors.png").string());
  }
  return 0;
}

int run(const CompareOptions& o) {
  compare::CompareConfig c;
  c.plugins = o.estimators;
  c.inclinations_deg = o.inclinations;
  c.rpms = o.rpms;
  c.snr_accel_db = o.snr_accel;
  c.snr_mag_db = o.snr_mag;
  c.azimuths_deg = o.azimuths;
  if (o.seeds < 1) throw std::invalid_argument("--seeds must be at least 1");
  c.seeds = o.seeds;
  c.base_seed = o.seed;
  if (o.duration_s <= 0 || o.rate_hz <= 0) throw std::invalid_argument("--duration and --rate-hz must be positive");
  c.base.duration_s = o.duration_s;
  c.base.sample_rate_hz = o.rate_hz;
  c.base.g = o.g;
  c.base.total_b = o.field;
  c.base.dip_deg = o.dip;
  if (!o.profile.empty()) c.base.rotation = sim::parse_profile(o.profile);
  if (!o.accel_bias.empty()) c.base.accel_errors.bias = parse_vector(o.accel_bias, "--accel-bias");
  if (!o.mag_bias.empty()) c.base.mag_errors.bias = parse_vector(o.mag_bias, "--mag-bias");
  c.assignments = o.params;
  const auto result = compare::run_compare(c, progress_printer("records"));
  compare::write_report(std::cout, result);
  if (!o.csv_path.empty()) {
    std::ofstream f(o.csv_path);
    if (!f) throw std::runtime_error("cannot write '" + o.csv_path + "'");
    compare::write_csv(f, result);
  }
  if (!o.plots_dir.empty()) {
    std::filesystem::create_directories(o.plots_dir);
    const std::string path = (std::filesystem::path(o.plots_dir) / "azimuth_points.csv").string();
    {
      std::ofstream f(path);
      if (!f) throw std::runtime_error("cannot write '" + path + "'");
      compare::write_azimuth_points_csv(f, result);
    }
    run_plot("compare-grid", path, o.plots_dir);
  }
  return 0;
}

// --scenario drilling's own options: the runs' grades and rates, and the families of depth and
// sensor noise the navigator is fed.
void add_drilling_options(CLI::App& cmd, CompareOptions& o) {
  cmd.add_option("--grade", o.grades, "drilling: IMU grades (navigation, tactical, mems, perfect)")->capture_default_str();
  cmd.add_option("--drilling-rate-hz", o.drilling_rates, "drilling: sampling rates, Hz")->capture_default_str();
  cmd.add_option("--depth", o.depth,
                  "drilling: how measured depth reaches the navigator, one or more of: yes (a depth sensor on every "
                  "row), no (none), both (yes and no), rig (as rigs deliver it: a report every second, rounded, late, "
                  "held or left empty between reports), tally (no depth sensor: the pipe tally, each joint's measured "
                  "length, as pipe_tally_m), all (yes, no, rig and tally); one table row per run of each")
      ->delimiter(',')
      ->capture_default_str();
  cmd.add_option("--depth-sd", o.depth_sd_m,
                  "drilling, --depth yes or rig: the simulated depth sensor's white noise, 1 sigma, m (0.01-0.05 is "
                  "a rig's; the navigator is not told: give --param depth_sd_m=... to tell it)")
      ->capture_default_str();
  cmd.add_option("--rig-interval", o.rig_interval_s, "drilling, --depth rig: seconds between depth reports")->capture_default_str();
  cmd.add_option("--rig-quantum", o.rig_quantum_m,
                  "drilling, --depth rig: each report rounded to this step, m (0.01; 0.03048 for 0.1 ft; 0: not rounded)")
      ->capture_default_str();
  cmd.add_option("--rig-late", o.rig_late_s, "drilling, --depth rig: each report tells the depth this many seconds before it arrives")
      ->capture_default_str();
  cmd.add_flag("--rig-empty", o.rig_empty,
                "drilling, --depth rig: rows between reports carry no depth (an empty depth_m cell) instead of the last report");
  cmd.add_option("--tally-sd", o.tally_sd_m,
                  "drilling, --depth tally: how well each joint is measured, 1 sigma, m (the joints are drawn with it "
                  "and the navigator told it as pipe_tally_sd_m)")
      ->capture_default_str();
  cmd.add_option("--noisier", o.noisier,
                  "drilling: the simulated gyro angle random walk and accelerometer noise are this many times their "
                  "grade's preset (e.g. --grade mems --noisier 1.5); the navigator is told only the grade")
      ->capture_default_str();
  cmd.add_flag("--no-magnetometer", o.no_magnetometer, "drilling: the tool has no magnetometer");
}

}  // namespace

void add_compare_verb(CLI::App& app, Verbs& verbs) {
  auto o = std::make_shared<CompareOptions>();
  auto* cmd = app.add_subcommand("compare",
                                 "Run estimator plugins over a grid of simulated scenarios (default: the source paper's "
                                 "reference grid) and print RMS and maximum errors beside the Cramér–Rao bound; with "
                                 "--input, on a recorded run instead");
  cmd->add_option("-e,--estimator,--plugin", o->estimators, "plugins to compare (--plugin, as for plumb-estimator, is the same)")->capture_default_str();
  cmd->add_option("--inclination", o->inclinations, "inclinations, deg")->capture_default_str();
  cmd->add_option("--rpm", o->rpms, "platform speeds, rpm")->capture_default_str();
  cmd->add_option("--snr-accel", o->snr_accel, "accelerometer SNRs, dB (docs/conventions.md)")->capture_default_str();
  cmd->add_option("--snr-mag", o->snr_mag, "magnetometer SNR, dB")->capture_default_str();
  cmd->add_option("--azimuth", o->azimuths, "azimuths, deg (default 0, 10, ..., 350)");
  cmd->add_option("--seeds", o->seeds, "Monte Carlo records per azimuth")->capture_default_str();
  cmd->add_option("--seed", o->seed, "first random seed")->capture_default_str();
  cmd->add_option("--profile", o->profile, "rotation profile with the grid speed as mean: stopgo:0:4, stickslip:0:2, ramp:...");
  cmd->add_option("--duration", o->duration_s, "record length, s")->capture_default_str();
  cmd->add_option("--rate-hz", o->rate_hz, "sampling rate, Hz")->capture_default_str();
  cmd->add_option("--g", o->g, "gravity, m/s^2")->capture_default_str();
  cmd->add_option("--field", o->field, "total field, uT")->capture_default_str();
  cmd->add_option("--dip", o->dip, "dip, deg")->capture_default_str();
  cmd->add_option("--accel-bias", o->accel_bias, "accelerometer bias x,y,z, m/s^2");
  cmd->add_option("--mag-bias", o->mag_bias, "magnetometer bias x,y,z, uT");
  components::add_param_option(*cmd, o->params);
  cmd->add_option("--plots", o->plots_dir, "draw error versus azimuth per inclination (or the drilling runs' errors over time) into this folder as PNG, with their data as CSV (plumb-plot, python3-matplotlib)");
  cmd->add_option("--csv", o->csv_path, "also write the table as CSV");
  cmd->add_option("--scenario", o->scenario,
                  "platform: the rotating-platform grid; drilling: 16-minute drilling runs through a navigator "
                  "(default estimator strapdown), beside the gyro inclinometer source's figures")
      ->check(CLI::IsMember({"platform", "drilling"}))
      ->capture_default_str();
  add_drilling_options(*cmd, *o);
  // On a recorded run instead of simulated ones.
  auto f = std::make_shared<CompareFileOptions>();
  cmd->add_option("-i,--input", f->input,
                  "compare the plugins on this sensor CSV or MCAP recording instead of simulated runs (no truth: each "
                  "plugin's spread and sigma, and its agreement with the first plugin)");
  cmd->add_option("-t,--topic", f->topic, "--input: sensor topic of a recording (default: plumb/sensor/calibrated when it holds messages, else plumb/sensor/raw)");
  cmd->add_option("-w,--window", f->window_s, "--input: estimator window, s (0: the whole file)")->capture_default_str();
  cmd->add_option("--match", f->match_s, "--input: rows of two plugins are compared when their times are at most this far apart, s")
      ->capture_default_str();
  cmd->add_flag("--skip-bad-rows", f->skip_bad_rows, "--input: report and skip bad CSV rows instead of stopping");
  components::add_import_options(*cmd, f->import);
  auto* estimator_option = cmd->get_option("--estimator");
  verbs.add(cmd, [o, f, cmd, estimator_option] {
    if (f->input.empty()) {
      for (const char* file_only : {"--topic", "--window", "--match", "--skip-bad-rows", "--column", "--units", "--axes"})
        if (cmd->get_option(file_only)->count() > 0)
          throw std::invalid_argument(std::string(file_only) + " applies to --input (a recorded run)");
      if (o->scenario == "drilling") return run_drilling(*o, *cmd, estimator_option->count() > 0);
      for (const char* drilling_only : kDrillingOnlyOptions)
        if (cmd->get_option(drilling_only)->count() > 0)
          throw std::invalid_argument(std::string(drilling_only) + " applies to --scenario drilling");
      return run(*o);
    }
    for (const char* simulation_only : {"--scenario", "--inclination", "--rpm", "--snr-accel", "--snr-mag", "--azimuth", "--seeds",
                                        "--seed", "--profile", "--duration", "--rate-hz", "--g", "--field", "--dip",
                                        "--accel-bias", "--mag-bias", "--plots"})
      if (cmd->get_option(simulation_only)->count() > 0)
        throw std::invalid_argument(std::string(simulation_only) + " describes simulated runs; it does not apply to --input " + f->input);
    for (const char* drilling_only : kDrillingOnlyOptions)
      if (cmd->get_option(drilling_only)->count() > 0)
        throw std::invalid_argument(std::string(drilling_only) + " describes simulated runs; it does not apply to --input " + f->input);
    f->estimators = o->estimators;
    f->params = o->params;
    f->csv_path = o->csv_path;
    return compare_file(*f);
  });
}

}  // namespace plumb::cli
