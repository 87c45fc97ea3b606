// plumb estimate: the estimator host's work offline, sensor CSV in, attitude CSV out.
#include <fstream>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/components/import_options.hpp"
#include "plumb/csv/files.hpp"
#include "plumb/components/convert.hpp"
#include "plumb/estimator/loader.hpp"
#include "recording.hpp"

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
  const csv::Import import = o.import.make();

  // The input: a recording (MCAP, plumb record) or a sensor CSV. A recording streams through
  // in chunks like a CSV (10 minutes at 10 kHz are 6 million samples: never all in memory).
  const bool recording = is_recording(o.input);
  std::ifstream in;
  std::unique_ptr<csv::SensorReader> reader;
  if (!recording) {
    if (!o.topic.empty()) throw std::invalid_argument("--topic applies to a recording (.mcap); " + o.input + " is not one");
    in.open(o.input);
    if (!in) throw std::runtime_error("cannot open input '" + o.input + "'");
    reader = std::make_unique<csv::SensorReader>(in, o.input, import);
    if (!csv::is_default(import)) std::cerr << "plumb estimate: reading " << o.input << " with " << csv::describe(import) << '\n';
  }
  const auto check_gyro = [&](bool has_gyro, const std::string& what) {
    if (has_gyro) return;
    for (const auto& name : runner.needing_gyro())
      throw std::invalid_argument("estimator '" + name + "' needs gyros, and " + o.input + " has no " + what);
  };
  if (!recording) check_gyro(reader->has_gyro(), "wx, wy, wz columns");
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
  const auto write = [&](const estimator::Runner::Slot&, Estimate& e) { csv::write_attitude_row(*out, e, navigation); };

  std::vector<Sample> chunk;
  std::size_t rows = 0, bad_rows = 0;
  bool units_checked = false;
  // The first chunk is the start of the file: seconds of data, enough to tell g from m/s^2.
  const auto push = [&] {
    start();
    if (!units_checked) {
      for (const auto& warning : csv::check_units(chunk, import)) std::cerr << "plumb estimate: warning: " << warning << '\n';
      units_checked = true;
    }
    runner.push(chunk, write);
    chunk.clear();
  };
  const auto consume = [&](const Sample& s) {
    ++rows;
    chunk.push_back(s);
    if (chunk.size() == 1024) push();
  };
  std::string recorded_topic;
  if (recording) {
    recorded_topic = read_recorded_batches("plumb estimate", o.input, o.topic, [&](const topics::SensorBatch& batch) {
      if (rows == 0 && !batch.samples.empty())
        check_gyro(batch.samples.front().flags & topics::SAMPLE_HAS_GYRO, "gyro samples on its sensor topic");
      for (const auto& s : batch.samples) consume(components::from_topic(s));
    });
  } else {
    while (true) {
      Sample s;
      try {
        if (!reader->next(s)) break;
      } catch (const csv::Error& e) {
        if (!o.skip_bad_rows) throw;
        ++bad_rows;
        std::cerr << "plumb estimate: skipped " << e.what() << '\n';
        continue;
      }
      consume(s);
    }
  }
  push();
  runner.flush(write);
  out->flush();

  std::cerr << "plumb estimate: " << rows << " samples from " << o.input;
  if (recording) std::cerr << " (" << recorded_topic << ")";
  if (bad_rows) std::cerr << " (" << bad_rows << " bad rows skipped)";
  std::cerr << '\n';
  for (const auto& slot : runner.slots()) {
    std::cerr << "  " << slot.name << ": " << slot.estimates << " estimate(s), " << slot.invalid << " invalid";
    for (const auto& [reason, n] : slot.estimator->counters()) std::cerr << ", " << n << " " << reason;
    std::cerr << '\n';
  }
  return 0;
}

}  // namespace

void add_estimate_command(CLI::App& app) {
  auto o = std::make_shared<EstimateOptions>();
  auto* cmd = app.add_subcommand("estimate", "Run estimator plugins offline on a sensor CSV; write an attitude CSV");
  cmd->add_option("-e,--estimator,--plugin", o->estimators, "estimator plugin name (repeat to run several side by side; --plugin, as for plumb-estimator, is the same)")->required();
  cmd->add_option("-i,--input", o->input, "sensor CSV (CONVENTIONS.md format) or MCAP recording (plumb record)")->required();
  cmd->add_option("-t,--topic", o->topic, "sensor topic of a recording (default: plumb/sensor/calibrated, else plumb/sensor/raw)");
  cmd->add_option("-o,--output", o->output, "attitude CSV to write (default: standard output)");
  cmd->add_option("-w,--window", o->window_s, "window length in seconds; 0 = the whole file (one row)")->capture_default_str();
  components::add_param_option(*cmd, o->params);
  cmd->add_flag("--skip-bad-rows", o->skip_bad_rows, "report and skip bad CSV rows instead of stopping");
  components::add_import_options(*cmd, o->import);
  cmd->callback([o] { g_exit_code = run_estimate(*o); });
}

}  // namespace plumb::cli
