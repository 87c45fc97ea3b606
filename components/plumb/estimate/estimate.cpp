// plumb estimate: the estimator host's work offline, sensor CSV in, attitude CSV out.
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "estimate/sample_input.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/components/import_options.hpp"
#include "plumb/csv/files.hpp"
#include "plumb/estimator/loader.hpp"
#include "verbs.hpp"

namespace plumb::cli {
namespace {

struct EstimateOptions {
  std::vector<std::string> estimators;
  std::string input;
  std::string topic;  // of a recording
  std::string output;
  double window_s = 0;
  std::vector<std::string> params;
  bool skip_bad_rows = false;
  components::ImportOptions import;
};

int run_estimate(const EstimateOptions& o) {
  if (o.window_s < 0) throw std::invalid_argument("--window must be >= 0 seconds (0: the whole file)");
  estimator::Runner runner = estimator::load_runner(o.estimators);
  runner.configure(o.params, o.window_s);
  bool navigation = false;
  for (const auto& info : runner.infos()) navigation = navigation || info.uses_gyro;

  std::ofstream file;
  std::ostream* out = &std::cout;
  // The output opens with the first samples, once the input proved usable (a recording says
  // whether it has gyros only with its first batch).
  bool started = false;
  const auto start = [&] {
    if (started) return;
    started = true;
    if (!o.output.empty()) {
      file.open(o.output);
      if (!file) throw std::runtime_error("cannot write output '" + o.output + "'");
      out = &file;
    }
    csv::write_attitude_header(*out, navigation);
  };
  const auto say_notices = [](estimator::Runner& r) {
    for (const std::string& text : r.take_notices()) std::cerr << "plumb estimate: " << text << '\n';
  };
  const auto write = [&](const estimator::Runner::Slot&, Estimate& e) { csv::write_attitude_row(*out, e, navigation); };
  const SampleInput input{"plumb estimate", o.input, o.topic, o.import.make(), o.skip_bad_rows};
  const SampleInputSummary summary = read_samples(
      input,
      require_gyros_for(runner, o.input),
      [&](const std::vector<Sample>& chunk) {
        start();
        runner.push(chunk, write);
        say_notices(runner);
      });
  runner.flush(write);
  say_notices(runner);
  out->flush();

  std::cerr << "plumb estimate: " << summary.describe(o.input) << '\n';
  for (const auto& slot : runner.slots()) {
    std::cerr << "  " << slot.name << ": " << slot.estimates << " estimate(s), " << slot.invalid << " invalid";
    for (const auto& [reason, n] : slot.estimator->counters()) std::cerr << ", " << n << " " << reason;
    std::cerr << '\n';
  }
  return check_valid_estimates("plumb estimate", runner);
}

}  // namespace

void add_estimate_verb(CLI::App& app, Verbs& verbs) {
  auto o = std::make_shared<EstimateOptions>();
  auto* cmd = app.add_subcommand("estimate", "Run estimator plugins offline on a sensor CSV; write an attitude CSV");
  cmd->add_option("-e,--estimator,--plugin", o->estimators, "estimator plugin name (repeat to run several side by side; --plugin, as for plumb-estimator, is the same)")->required();
  cmd->add_option("-i,--input", o->input, "sensor CSV (docs/conventions.md format) or MCAP recording (plumb record)")->required();
  cmd->add_option("-t,--topic", o->topic, "sensor topic of a recording (default: plumb/sensor/calibrated when it holds messages, else plumb/sensor/raw)");
  cmd->add_option("-o,--output", o->output, "attitude CSV to write (default: standard output)");
  cmd->add_option("-w,--window", o->window_s, "window length in seconds; 0 = the whole file (one row)")->capture_default_str();
  components::add_param_option(*cmd, o->params);
  cmd->add_flag("--skip-bad-rows", o->skip_bad_rows, "report and skip bad CSV rows instead of stopping");
  components::add_import_options(*cmd, o->import);
  verbs.add(cmd, [o] { return run_estimate(*o); });
}

}  // namespace plumb::cli
