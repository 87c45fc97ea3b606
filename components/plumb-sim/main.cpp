// plumb-sim: the simulated rotating platform, a drilling run or a foot-mounted walk (sim/) as a
// component. Publishes
// sensor batches on plumb/sensor/raw (or any sensor topic) and the truth on plumb/sim/truth, paced
// in real time, or writes the same run as CSV files.
#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "csv_sink.hpp"
#include "dds_sink.hpp"
#include "pacing.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/sim/drilling.hpp"
#include "plumb/sim/platform.hpp"
#include "plumb/sim/walk.hpp"
#include "plumb/transport/topic_names.hpp"
#include "scenario_options.hpp"
#include "serial_sink.hpp"

namespace plumb::sim_component {
namespace {

constexpr const char* kProgram = "plumb-sim";

struct OutputOptions {
  components::TransportOptions transport;
  std::string topic = transport::topic_names::kSensorRaw;
  std::string truth_topic = transport::topic_names::kSimTruth;
  bool no_truth = false;
  std::string rate = "realtime";
  int batch = 10;
  bool reliable = false;
  double wait_subscribers_s = 5;
  double linger_s = 1;
  std::string csv_dir;
  bool loop = false;
  SerialSinkOptions serial;
  double rig_clock_offset_s = 0;
  double rig_clock_drift_ppm = 0;
  std::string wits_to;
};

void add_output_options(CLI::App& app, OutputOptions& o) {
  components::add_transport_options(app, o.transport);
  app.add_option("--topic", o.topic, "sensor topic to publish on (e.g. plumb/sensor/calibrated to skip the bridge)")
      ->capture_default_str();
  app.add_option("--truth-topic", o.truth_topic, "topic for the truth, one message per batch")->capture_default_str();
  app.add_flag("--no-truth", o.no_truth, "do not publish the truth");
  app.add_option("--rate", o.rate, "pacing: realtime, xN (N times faster) or max")->capture_default_str();
  app.add_option("--batch", o.batch, "samples per batch (1..32)")->capture_default_str()->check(CLI::Range(1, 32));
  app.add_flag("--reliable", o.reliable, "reliable sensor stream (nothing lost) instead of best effort");
  app.add_option("--wait-subscribers", o.wait_subscribers_s,
                 "seconds to wait at most for a reader of the sensor topic before starting, and with --wits for "
                 "plumb-wits to listen (default 5 s, with --wits 20 s; 0: do not wait)");
  app.add_option("--linger", o.linger_s, "seconds to stay after the last batch so reliable readers catch up")
      ->capture_default_str();
  app.add_option("--csv", o.csv_dir, "write DIR/sensor.csv and DIR/truth.csv instead of publishing");
  app.add_option("--serial", o.serial.path,
                 "write the sensor board protocol (docs/protocol.md) into a pseudo-terminal linked at PATH "
                 "(or into PATH if it is a serial device) instead of publishing; use --batch 1 for per-sample timing");
  app.add_option("--serial-baud", o.serial.baud, "baud rate when --serial names a real device")->capture_default_str();
  app.add_option("--serial-mode", o.serial.mode, "--serial protocol: binary or ascii")->capture_default_str();
  app.add_option("--rig-clock-offset", o.rig_clock_offset_s,
                 "stamp the published depth on a rig clock this many seconds ahead of the sensors' (negative: "
                 "behind), as a rig's own clock is: for tests of the depth clock's alignment")
      ->capture_default_str();
  app.add_option("--rig-clock-drift-ppm", o.rig_clock_drift_ppm,
                 "and running this many parts per million fast (negative: slow) from sensor time 0")
      ->capture_default_str()
      ->check(CLI::Range(-1000.0, 1000.0));
  app.add_option("--wits", o.wits_to,
                 "drilling: play the rig too: its depth as a WITS level-0 feed (a frame a second) to plumb-wits "
                 "--listen at HOST:PORT instead of plumb/depth; plumb-wits stamps it with this computer's clock, and "
                 "the sensors are stamped on the tool's, --rig-clock-offset behind it and --rig-clock-drift-ppm slow "
                 "(real time only)");
  app.add_flag("--loop", o.loop,
               "keep simulating past the duration until Ctrl-C (the platform keeps turning; a drilling tool or a "
               "walking foot stays still where its run ended)");
}

std::unique_ptr<Sink> make_sink(const OutputOptions& o, const std::string& tool_id, const CsvColumns& columns) {
  if (!o.csv_dir.empty() && !o.serial.path.empty()) throw std::invalid_argument("give --csv or --serial, not both");
  if (!o.csv_dir.empty()) return std::make_unique<CsvSink>(o.csv_dir, columns);
  if (!o.serial.path.empty()) return std::make_unique<SerialSink>(o.serial);
  const auto* type = transport::topic_type_for(o.topic);
  if (type && *type != topics::type_support<topics::SensorBatch>())
    throw std::invalid_argument("--topic " + o.topic + " is not a sensor topic (expected plumb/sensor/...)");
  DdsSinkOptions d;
  d.transport = o.transport;
  d.sensor_topic = o.topic;
  d.truth_topic = o.no_truth ? "" : o.truth_topic;
  d.reliable = o.reliable;
  d.wait_subscribers_s = o.wait_subscribers_s;
  d.linger_s = o.linger_s;
  d.tool_id = tool_id;
  d.rig_clock_offset_s = o.rig_clock_offset_s;
  d.rig_clock_drift = o.rig_clock_drift_ppm * 1e-6;
  d.wits_to = o.wits_to;
  return std::make_unique<DdsSink>(d);
}

std::string pacing_text(double speed) {
  if (speed <= 0) return "as fast as possible";
  if (speed == 1) return "real time";
  std::ostringstream out;
  out << speed << " x real time";
  return out.str();
}

struct RunResult {
  std::uint64_t samples = 0;
  std::uint64_t batches = 0;
};

// Simulator: PlatformSimulator, DrillingSimulator or WalkSimulator (next, done).
template <typename Simulator>
RunResult run(Simulator& simulator, double rate_hz, Sink& sink, double speed, std::size_t batch_size, bool loop) {
  Pacer pacer(sink.paced() ? speed : 0.0);
  RunResult result;
  std::vector<Sample> samples;
  std::vector<TruthSample> truth;
  samples.reserve(batch_size);
  truth.reserve(batch_size);
  const double period = 1.0 / rate_hz;
  // A paced run says every few seconds how far it is: nobody should wait on it in silence.
  constexpr auto kProgressEvery = std::chrono::seconds(5);
  auto next_progress = std::chrono::steady_clock::now() + kProgressEvery;
  while (!components::g_stop && (loop || !simulator.done())) {
    samples.clear();
    truth.clear();
    while (samples.size() < batch_size && (loop || !simulator.done())) {
      TruthSample t;
      samples.push_back(simulator.next(&t));
      truth.push_back(t);
    }
    // A batch leaves when its last sample has been measured, one period after its stamp.
    pacer.wait_until(samples.back().t + period);
    if (components::g_stop) break;
    sink.write(samples, truth);
    result.samples += samples.size();
    ++result.batches;
    if (sink.paced() && std::chrono::steady_clock::now() >= next_progress) {
      next_progress += kProgressEvery;
      std::cout << kProgram << ": " << std::fixed << std::setprecision(1) << samples.back().t << " s of the run sent ("
                << result.samples << " samples)" << std::defaultfloat << std::endl;
    }
  }
  return result;
}

// One simulator, its sink and its log lines, for either kind of run.
template <typename Simulator>
int simulate(Simulator& simulator, const std::string& description, double rate_hz, const std::string& tool_id,
             const CsvColumns& columns, const OutputOptions& output_options) {
  const double speed = components::parse_rate_option(output_options.rate);
  if (output_options.loop && !output_options.csv_dir.empty())
    throw std::invalid_argument("--loop cannot be used with --csv (the files would never end)");
  if (!output_options.wits_to.empty() && (speed != 1 || !output_options.csv_dir.empty() || !output_options.serial.path.empty()))
    throw std::invalid_argument("--wits plays the rig in real time on DDS: plumb-wits stamps its frames with this "
                                "computer's clock (no --rate other than realtime, no --csv or --serial)");
  if (simulator.sample_count() == 0 && !output_options.loop)
    throw std::invalid_argument("the scenario has no samples (duration x rate < 1)");

  components::install_stop_handler();
  auto sink = make_sink(output_options, tool_id, columns);
  std::cout << kProgram << ": simulating " << description << " -> " << sink->describe() << ", "
            << pacing_text(sink->paced() ? speed : 0.0) << (output_options.loop ? ", looping until Ctrl-C" : "")
            << std::endl;
  if (columns.depth && !sink->carries_depth())
    std::cout << kProgram << ": the measured depth is not carried by " << sink->describe() << "; use --csv for it"
              << std::endl;
  if (!sink->start()) {
    std::cout << kProgram << ": stopped before starting" << std::endl;
    return 0;
  }
  const RunResult result = run(simulator, rate_hz, *sink, speed, static_cast<std::size_t>(output_options.batch),
                               output_options.loop);
  const bool interrupted = components::g_stop;
  sink->finish(interrupted);
  std::cout << kProgram << ": " << (interrupted ? "stopped; " : "done; ") << result.samples << " samples in "
            << result.batches << " batches to " << sink->describe() << std::endl;
  return 0;
}

int run_main(int argc, char** argv) {
  CLI::App app{"plumb-sim: simulated rotating sensor platform (accelerometers, magnetometers, gyros), or a drilling "
               "run for the strapdown navigator (--scenario drilling: gyros, measured depth, truth position), or a "
               "foot-mounted IMU walking a closed loop (--scenario walk: gyros, truth position), publishing sensor "
               "batches and the truth over DDS, or writing them as CSV"};
  app.name(kProgram);
  ScenarioOptions scenario_options;
  OutputOptions output_options;
  add_scenario_options(app, scenario_options);
  add_output_options(app, output_options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return plumb::components::exit_on_parse_error(app, e);
  }
  // plumb-wits may be starting beside the simulator (a launch file, a slow computer): the rig waits
  // longer for it than for a sensor reader, unless told otherwise.
  if (!output_options.wits_to.empty() && app.count("--wait-subscribers") == 0) output_options.wait_subscribers_s = 20;

  try {
    if (is_drilling(scenario_options)) {
      const sim::DrillingScenario scenario = make_drilling_scenario(app, scenario_options);
      sim::DrillingSimulator simulator(scenario);
      const CsvColumns columns{true, scenario.temperature.enabled, scenario.depth.present, true};
      return simulate(simulator, sim::describe(scenario), scenario.sample_rate_hz, scenario.tool_id, columns,
                      output_options);
    }
    if (!output_options.wits_to.empty() && !is_drilling(scenario_options))
      throw std::invalid_argument("--wits needs a drilling run (--scenario drilling or drilling-survey): only they have a rig");
    if (is_walk(scenario_options)) {
      const sim::WalkScenario scenario = make_walk_scenario(app, scenario_options);
      sim::WalkSimulator simulator(scenario);
      const CsvColumns columns{true, false, false, true};
      return simulate(simulator, sim::describe(scenario), scenario.sample_rate_hz, scenario.tool_id, columns,
                      output_options);
    }
    const sim::Scenario scenario = make_scenario(app, scenario_options);
    sim::PlatformSimulator simulator(scenario);
    const CsvColumns columns{scenario.with_gyro, true, false, false};
    return simulate(simulator, sim::describe(scenario), scenario.sample_rate_hz, scenario.tool_id, columns,
                    output_options);
  } catch (const std::exception& e) {
    return components::exit_on_error(kProgram, e);
  }
}

}  // namespace
}  // namespace plumb::sim_component

int main(int argc, char** argv) { return plumb::sim_component::run_main(argc, argv); }
