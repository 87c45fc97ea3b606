// plumb estimate: the estimator host's work offline, sensor CSV in, attitude CSV out.
#include <fstream>
#include <iostream>
#include <map>
#include <memory>

#include "commands.hpp"
#include "plumb/core/csv.hpp"
#include "plumb/estimator/assignments.hpp"
#include "plumb/estimator/loader.hpp"

namespace plumb::cli {
namespace {

struct EstimateOptions {
  std::vector<std::string> estimators;
  std::string input;
  std::string output;
  double window_s = 0;
  std::vector<std::string> params;
  bool skip_bad_rows = false;
};

int run_estimate(const EstimateOptions& o) {
  if (o.window_s < 0) throw std::invalid_argument("--window must be >= 0 seconds (0: the whole file)");
  std::vector<estimator::EstimatorPtr> estimators;
  for (const auto& name : o.estimators) estimators.push_back(estimator::load_estimator(name));
  std::vector<estimator::Info> infos;
  for (const auto& e : estimators) infos.push_back(e->info());
  const auto params = estimator::assign_parameters(infos, o.params, o.window_s);
  for (std::size_t i = 0; i < estimators.size(); ++i) estimators[i]->configure(params[i]);

  std::ifstream in(o.input);
  if (!in) throw std::runtime_error("cannot open input '" + o.input + "'");
  csv::SensorReader reader(in, o.input);

  std::ofstream file;
  if (!o.output.empty()) {
    file.open(o.output);
    if (!file) throw std::runtime_error("cannot write output '" + o.output + "'");
  }
  std::ostream& out = o.output.empty() ? std::cout : file;
  csv::write_attitude_header(out);

  std::vector<Sample> chunk;
  std::vector<Estimate> estimates;
  std::size_t rows = 0, bad_rows = 0;
  std::map<std::string, std::pair<std::size_t, std::size_t>> tally;  // estimator -> (estimates, invalid)
  auto emit = [&] {
    for (const auto& e : estimates) {
      csv::write_attitude_row(out, e);
      auto& t = tally[e.estimator];
      ++t.first;
      if (!e.valid) ++t.second;
    }
    estimates.clear();
  };
  auto feed = [&] {
    for (auto& est : estimators) est->push(chunk, estimates);
    emit();
    chunk.clear();
  };
  while (true) {
    Sample s;
    try {
      if (!reader.next(s)) break;
    } catch (const csv::Error& e) {
      if (!o.skip_bad_rows) throw;
      ++bad_rows;
      std::cerr << "plumb estimate: skipped " << e.what() << '\n';
      continue;
    }
    ++rows;
    chunk.push_back(s);
    if (chunk.size() == 1024) feed();
  }
  feed();
  for (auto& est : estimators) est->flush(estimates);
  emit();
  out.flush();

  std::cerr << "plumb estimate: " << rows << " samples from " << o.input;
  if (bad_rows) std::cerr << " (" << bad_rows << " bad rows skipped)";
  std::cerr << '\n';
  for (const auto& est : estimators) {
    const auto& t = tally[est->info().name];
    std::cerr << "  " << est->info().name << ": " << t.first << " estimate(s), " << t.second << " invalid";
    for (const auto& [reason, n] : est->counters()) std::cerr << ", " << n << " " << reason;
    std::cerr << '\n';
  }
  return 0;
}

}  // namespace

void add_estimate_command(CLI::App& app) {
  auto o = std::make_shared<EstimateOptions>();
  auto* cmd = app.add_subcommand("estimate", "Run estimator plugins offline on a sensor CSV; write an attitude CSV");
  cmd->add_option("-e,--estimator", o->estimators, "estimator plugin name (repeat to run several side by side)")->required();
  cmd->add_option("-i,--input", o->input, "sensor CSV (CONVENTIONS.md format)")->required();
  cmd->add_option("-o,--output", o->output, "attitude CSV to write (default: standard output)");
  cmd->add_option("-w,--window", o->window_s, "window length in seconds; 0 = the whole file (one row)")->capture_default_str();
  cmd->add_option("-p,--param", o->params, "plugin parameter KEY=VALUE (see plumb plugins -v)");
  cmd->add_flag("--skip-bad-rows", o->skip_bad_rows, "report and skip bad CSV rows instead of stopping");
  cmd->callback([o] { g_exit_code = run_estimate(*o); });
}

}  // namespace plumb::cli
