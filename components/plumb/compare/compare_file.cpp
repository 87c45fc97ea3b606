#include "compare/compare_file.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>

#include "estimate/sample_input.hpp"
#include "plumb/compare/agreement.hpp"
#include "plumb/estimator/loader.hpp"

namespace plumb::cli {
namespace {

std::string fraction(double f) {
  if (f < 0) return "-";
  char text[16];
  std::snprintf(text, sizeof text, "%.1f %%", 100.0 * f);
  return text;
}

std::string degrees(double value) {
  char text[24];
  std::snprintf(text, sizeof text, "%.4f", value);
  return text;
}

}  // namespace

int compare_file(const CompareFileOptions& o) {
  if (o.window_s < 0) throw std::invalid_argument("--window must be >= 0 seconds (0: the whole file)");
  if (!(o.match_s > 0)) throw std::invalid_argument("--match must be > 0 seconds");
  estimator::Runner runner = estimator::load_runner(o.estimators);
  runner.configure(o.params, o.window_s);
  std::map<std::string, std::vector<Estimate>> rows;
  const auto keep = [&](const estimator::Runner::Slot& slot, Estimate& e) { rows[slot.name].push_back(e); };
  const SampleInput input{"plumb compare", o.input, o.topic, o.import.make(), o.skip_bad_rows};
  const SampleInputSummary summary = read_samples(
      input,
      require_gyros_for(runner, o.input),
      [&](const std::vector<Sample>& chunk) { runner.push(chunk, keep); });
  runner.flush(keep);

  const std::string& reference = runner.slots().front().name;
  std::printf("plumb compare: %zu plugin(s) on %s; agreement with %s, rows at most %.3g s apart\n",
              runner.slots().size(), summary.describe(o.input).c_str(), reference.c_str(), o.match_s);
  std::printf("%-14s %6s %6s %22s %22s %16s %10s %10s %9s %9s\n", "plugin", "rows", "valid", "inclination, deg",
              "azimuth, deg", "median sigma I/A", "RMS dI", "RMS dA", "I in 2s", "A in 2s");
  std::ofstream csv;
  if (!o.csv_path.empty()) {
    csv.open(o.csv_path);
    if (!csv) throw std::runtime_error("cannot write '" + o.csv_path + "'");
    csv.precision(10);
    csv << "plugin,rows,valid,azimuth_valid,inclination_mean_deg,inclination_sd_deg,azimuth_mean_deg,azimuth_sd_deg,"
           "median_inclination_sigma_deg,median_azimuth_sigma_deg,reference,matched,rms_inclination_diff_deg,"
           "rms_azimuth_diff_deg,inclination_within_2sigma,azimuth_within_2sigma\n";
  }
  for (const auto& slot : runner.slots()) {
    const std::vector<Estimate>& mine = rows[slot.name];
    const compare::PluginSummary s = compare::summarize(slot.name, mine);
    const compare::Agreement a = compare::agree(rows[reference], mine, o.match_s);
    char inclination[32], azimuth[32], sigma[32];
    std::snprintf(inclination, sizeof inclination, "%.3f +- %.3f", s.inclination_mean_deg, s.inclination_sd_deg);
    std::snprintf(azimuth, sizeof azimuth, "%.2f +- %.2f", s.azimuth_mean_deg, s.azimuth_sd_deg);
    std::snprintf(sigma, sizeof sigma, "%.3f / %.3f", s.median_inclination_sigma_deg, s.median_azimuth_sigma_deg);
    const bool self = slot.name == reference;
    std::printf("%-14s %6zu %6zu %22s %22s %16s %10s %10s %9s %9s\n", slot.name.c_str(), s.rows, s.valid, inclination,
                s.azimuth_valid ? azimuth : "-", sigma, self ? "-" : degrees(a.rms_inclination_diff_deg).c_str(),
                self ? "-" : degrees(a.rms_azimuth_diff_deg).c_str(),
                self ? "-" : fraction(a.inclination_within_2sigma).c_str(), self ? "-" : fraction(a.azimuth_within_2sigma).c_str());
    if (csv) {
      csv << s.name << ',' << s.rows << ',' << s.valid << ',' << s.azimuth_valid << ',' << s.inclination_mean_deg << ','
          << s.inclination_sd_deg << ',' << s.azimuth_mean_deg << ',' << s.azimuth_sd_deg << ','
          << s.median_inclination_sigma_deg << ',' << s.median_azimuth_sigma_deg << ',' << reference << ',' << a.matched
          << ',' << a.rms_inclination_diff_deg << ',' << a.rms_azimuth_diff_deg << ',' << a.inclination_within_2sigma
          << ',' << a.azimuth_within_2sigma << '\n';
    }
  }
  if (runner.slots().size() > 1)
    std::printf("RMS dI, dA: against %s; in 2s: share of rows within 2 sqrt(s1^2 + s2^2) of it (about 95 %% when both are right)\n",
                reference.c_str());
  std::fflush(stdout);  // the table before the lines on stderr that say which plugin failed
  return check_valid_estimates("plumb compare", runner);
}

}  // namespace plumb::cli
