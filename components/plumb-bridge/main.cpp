// plumb-bridge: the tool computer's hardware bridge. Reads the sensor board (a serial device,
// docs/protocol.md) or replays a sensor CSV, checks every sample, and publishes raw and
// calibrated sensor batches plus its own status once a second.
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <CLI/CLI.hpp>

#include "batcher.hpp"
#include "plumb/bridge/device_source.hpp"
#include "plumb/bridge/replay_source.hpp"
#include "plumb/bridge/sample_checker.hpp"
#include "plumb/csv/coefficients_file.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/components/import_options.hpp"
#include "plumb/transport/topic_names.hpp"
#include "publisher.hpp"

namespace plumb::bridge_component {
namespace {

constexpr const char* kProgram = "plumb-bridge";
constexpr double kReplayWaitS = 5;
using Clock = std::chrono::steady_clock;

struct Options {
  components::TransportOptions transport;
  std::string device;
  int baud = 115200;
  std::string mode = "auto";
  std::string replay;
  std::string rate = "realtime";
  components::ImportOptions import;
  bool strict = false;
  std::string calibration_file;
  bool no_calibration_topic = false;
  PublisherOptions publish{transport::topic_names::kSensorRaw, transport::topic_names::kSensorCalibrated,
                           transport::topic_names::kCalibration, transport::topic_names::kStatus,
                           BindingRule{"board"}};
  bridge::Limits limits;
  double status_period_s = 1.0;
  double backoff_min_s = 0.1;
  double backoff_max_s = 5.0;
  double duration_s = 0;
  // Negative: not given. A replay then waits up to kReplayWaitS; a device does not wait, because
  // its kernel buffer would overflow meanwhile (and a live stream has no start to keep).
  double wait_subscribers_s = -1;
  double linger_s = 1.0;
  int max_logged_errors = 20;
};

void add_options(CLI::App& app, Options& o) {
  components::add_transport_options(app, o.transport);
  auto* device = app.add_option("--device", o.device, "serial device of the sensor board (e.g. /dev/ttyUSB0)");
  app.add_option("--baud", o.baud, "baud rate (a standard rate)")->capture_default_str();
  app.add_option("--mode", o.mode, "wire protocol: auto (detected), binary or ascii")
      ->check(CLI::IsMember({"auto", "binary", "ascii"}))
      ->capture_default_str();
  auto* replay = app.add_option("--replay", o.replay, "replay a sensor CSV file instead of reading a device");
  app.add_option("--rate", o.rate, "replay pace: realtime, xN (N times faster) or max")->capture_default_str();
  app.add_flag("--strict", o.strict, "replay: stop with exit code 1 at the first bad row (default: count, go on)");
  device->excludes(replay);
  components::add_import_options(app, o.import);
  app.add_option("--calibration", o.calibration_file, "coefficients file (docs/calibration.md) to apply from the start");
  app.add_flag("--no-calibration-topic", o.no_calibration_topic, "ignore coefficients published on plumb/calibration");
  app.add_option("--tool-id", o.publish.binding.tool_id,
                 "this bridge's tool: put in the batches; only coefficients made for this tool id are applied")
      ->capture_default_str();
  app.add_flag("--calibration-any-tool", o.publish.binding.any_tool,
               "apply coefficients made for another tool or for none (bench work; logged)");
  app.add_option("--accel-units", o.publish.binding.accel_units,
                 "units of the stream's accelerometer channels; coefficients made for other units are refused")
      ->capture_default_str();
  app.add_option("--mag-units", o.publish.binding.mag_units,
                 "units of the stream's magnetometer channels; coefficients made for other units are refused")
      ->capture_default_str();
  app.add_option("--g", o.publish.g, "local gravity, m/s^2: the calibrated stream's |G| is checked against it")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--gravity-tolerance", o.publish.gravity_tolerance,
                 "relative tolerance of that check; beyond it the calibrated stream stops")
      ->check(CLI::Range(0.001, 0.9))
      ->capture_default_str();
  app.add_option("--raw-topic", o.publish.raw_topic, "topic of raw batches")->capture_default_str();
  app.add_option("--calibrated-topic", o.publish.calibrated_topic, "topic of calibrated batches")->capture_default_str();
  app.add_flag("--reliable", o.publish.reliable, "reliable sensor topics (nothing lost) instead of best effort");
  app.add_option("--accel-full-scale", o.limits.accel_full_scale, "accelerometer saturation, m/s^2")->capture_default_str();
  app.add_option("--accel-max", o.limits.accel_max, "accelerometer out-of-range limit, m/s^2")->capture_default_str();
  app.add_option("--mag-full-scale", o.limits.mag_full_scale, "magnetometer saturation, uT")->capture_default_str();
  app.add_option("--mag-max", o.limits.mag_max, "magnetometer out-of-range limit, uT")->capture_default_str();
  app.add_option("--gyro-full-scale", o.limits.gyro_full_scale, "gyro saturation, rad/s")->capture_default_str();
  app.add_option("--gyro-max", o.limits.gyro_max, "gyro out-of-range limit, rad/s")->capture_default_str();
  app.add_option("--temp-min", o.limits.temp_min_c, "lowest plausible temperature, degC")->capture_default_str();
  app.add_option("--temp-max", o.limits.temp_max_c, "highest plausible temperature, degC")->capture_default_str();
  app.add_option("--status-period", o.status_period_s, "seconds between status messages")
      ->check(CLI::Range(0.05, 3600.0))
      ->capture_default_str();
  app.add_option("--backoff-min", o.backoff_min_s, "first reopen delay after the device went away, s")
      ->check(CLI::Range(0.001, 60.0))
      ->capture_default_str();
  app.add_option("--backoff-max", o.backoff_max_s, "longest reopen delay, s")->check(CLI::Range(0.001, 600.0))->capture_default_str();
  app.add_option("--duration", o.duration_s, "stop after this many seconds (0: run until Ctrl-C or the replay ends)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--wait-subscribers", o.wait_subscribers_s,
                 "seconds to wait at most for a sensor topic reader before reading the source, so that a replay "
                 "loses no start (default: 5 with --replay, 0 with --device; 0: publish at once)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--linger", o.linger_s, "seconds to stay after the end so reliable readers catch up")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--max-logged-errors", o.max_logged_errors, "bad rows/lines printed; later ones are only counted")
      ->capture_default_str();
}

std::string seconds_text(double s) {
  std::ostringstream out;
  out << s;
  return out.str();
}

void log(const std::string& line) { std::cout << kProgram << ": " << line << std::endl; }

std::string summary(const bridge::Counters& c) {
  std::ostringstream out;
  bool first = true;
  for (const auto& [name, value] : c.named()) {
    if (value == 0) continue;
    out << (first ? "" : ", ") << name << "=" << value;
    first = false;
  }
  return first ? std::string("nothing counted") : out.str();
}

// The options that CLI11 cannot check alone; the import of --replay files they give.
csv::Import checked_import(const Options& o) {
  if (o.device.empty() == o.replay.empty()) throw std::invalid_argument("give either --device PATH or --replay FILE.csv");
  if (o.limits.accel_full_scale <= 0 || o.limits.mag_full_scale <= 0 || o.limits.gyro_full_scale <= 0 ||
      o.limits.temp_min_c >= o.limits.temp_max_c)
    throw std::invalid_argument("limits: full scales must be > 0 and --temp-min below --temp-max");
  if (o.backoff_min_s > o.backoff_max_s) throw std::invalid_argument("--backoff-min is above --backoff-max");
  const csv::Import import = o.import.make();
  if (!o.device.empty() && !csv::is_default(import))
    throw std::invalid_argument("--column, --units and --axes apply to --replay files, not to --device");
  return import;
}

// Bad rows and lines: the first --max-logged-errors printed, the later ones only counted.
class BadInputLog {
 public:
  explicit BadInputLog(int max_logged) : max_logged_(max_logged) {}
  void operator()(const std::string& what) {
    if (logged_ < max_logged_) std::cerr << kProgram << ": " << what << std::endl;
    if (++logged_ == max_logged_)
      std::cerr << kProgram << ": further bad rows are counted (csv_errors) but not printed" << std::endl;
  }

 private:
  int max_logged_;
  int logged_ = 0;
};

// The CSV replay, or the serial device with its reopening said in the log.
std::unique_ptr<bridge::SampleSource> open_source(const Options& o, const csv::Import& import, bridge::Counters& counters,
                                                  bridge::SampleChecker& checker, BadInputLog& bad_input) {
  if (!o.replay.empty()) {
    const double speed = components::parse_rate_option(o.rate);
    return std::make_unique<bridge::ReplaySource>(
        o.replay, speed, counters, o.strict,
        [&bad_input](const csv::Error& e) { bad_input(std::string(e.what()) + " (row skipped)"); }, import,
        [](const std::string& warning) { std::cerr << kProgram << ": warning: " << warning << std::endl; });
  }
  bridge::SerialOptions serial;
  serial.path = o.device;
  serial.baud = o.baud;
  serial.backoff_min = std::chrono::milliseconds(std::llround(o.backoff_min_s * 1000));
  serial.backoff_max = std::chrono::milliseconds(std::llround(o.backoff_max_s * 1000));
  const auto on_event = [&checker, backoff_min_s = o.backoff_min_s, backoff_max_s = o.backoff_max_s](
                            bridge::SerialPort::Event e, const std::string& what) {
    if (e == bridge::SerialPort::Event::Opened) log("opened " + what);
    if (e == bridge::SerialPort::Event::Closed) {
      log("device lost (" + what + "); reopening with back-off");
      checker.new_stream();
    }
    if (e == bridge::SerialPort::Event::OpenFailed)
      log(what + "; retrying with back-off (" + seconds_text(backoff_min_s) + " s .. " + seconds_text(backoff_max_s) +
          " s), reported again at attempts 2, 4, 8...");
  };
  return std::make_unique<bridge::DeviceSource>(serial, *bridge::parse_mode(o.mode), counters, on_event);
}

// --calibration, refused before anything starts when it does not bind to this tool: a bridge that
// would publish raw data only is not what was asked.
CalibrationModel calibration_from_file(const Options& o) {
  CalibrationModel model;
  if (o.calibration_file.empty()) return model;
  model = csv::read_calibration_file(o.calibration_file);
  if (const auto problem = binding_problem(model, o.publish.binding); !problem.empty())
    throw std::invalid_argument(o.calibration_file + ": " + problem);
  return model;
}

// A replay published before discovery matched its reader goes to nobody (or starts in the middle):
// wait, bounded, for a reader, and say what happened.
void wait_for_sensor_readers(const Options& o, const PublisherOptions& po, const Publisher& publisher) {
  const double wait_s = o.wait_subscribers_s >= 0 ? o.wait_subscribers_s : (o.replay.empty() ? 0.0 : kReplayWaitS);
  if (wait_s <= 0) return;
  log("waiting up to " + seconds_text(wait_s) + " s for a reader of " + po.raw_topic + " or " + po.calibrated_topic);
  const auto start = Clock::now();
  const auto until = start + std::chrono::duration<double>(wait_s);
  while (publisher.sensor_readers() == 0 && Clock::now() < until && !components::g_stop)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const double waited_s = std::chrono::duration<double>(Clock::now() - start).count();
  if (publisher.sensor_readers() == 0)
    log("no reader after " + seconds_text(wait_s) + " s; publishing anyway");
  else
    log(std::to_string(publisher.sensor_readers()) + " sensor topic reader(s) matched after " +
        seconds_text(std::round(waited_s * 100) / 100) + " s; publishing");
}

// Says what is read and published where, applies --calibration, and says whether coefficients are
// still awaited.
void start_publishing(const Options& o, const PublisherOptions& po, const components::Connection& connection,
                      const bridge::SampleSource& source, Publisher& publisher, const CalibrationModel& file_model) {
  log("reading " + source.describe() + " -> " + connection.transport->name() + " " + po.raw_topic + " and " +
      po.calibrated_topic + " (" + (po.reliable ? "reliable" : "best effort") + "), status on " + po.status_topic);
  if (!o.calibration_file.empty() && !publisher.set_calibration(file_model, o.calibration_file))
    throw std::runtime_error(o.calibration_file + ": coefficients cannot be applied");
  publisher.poll_calibration();
  if (!publisher.has_calibration())
    log("no calibration yet: raw data flows on " + po.raw_topic + "; " + po.calibrated_topic +
        " starts once coefficients arrive" + (po.calibration_topic.empty() ? "" : " on " + po.calibration_topic));
  wait_for_sensor_readers(o, po, publisher);
}

// The bridge's loop: samples from the source, checked, batched and published; coefficients polled;
// status once a period; silence said at 5, 10, 20... s without a sample.
class Pump {
 public:
  Pump(const Options& o, bridge::SampleSource& source, bridge::SampleChecker& checker, Publisher& publisher,
       bridge::Counters& counters)
      : o_(o), source_(source), checker_(checker), publisher_(publisher), counters_(counters) {}

  // Until Ctrl-C, the end of the source or --duration. A --strict replay's bad row ends it with
  // what was batched published and a failed status, then goes on up.
  void run() {
    try {
      while (!components::g_stop && step()) {
      }
    } catch (const csv::Error& e) {
      publisher_.publish(batcher_.take());
      publisher_.finish();
      publisher_.publish_status("failed", e.what());
      log("stopped at the first bad row (--strict); " + summary(counters_));
      throw;
    }
    publisher_.publish(batcher_.take());
    publisher_.finish();
    if (!source_.last_error().empty()) last_error_ = source_.last_error();
  }

  std::uint64_t total_samples() const { return total_samples_; }
  const std::string& last_error() const { return last_error_; }

 private:
  // One poll of the source; false when the source ended or --duration is over.
  bool step() {
    samples_.clear();
    const bool source_alive = source_.poll(samples_, std::chrono::milliseconds(10));
    const auto now = Clock::now();
    note_samples(now);
    for (auto& s : samples_) {
      if (checker_.check(s) && batcher_.add(s, now)) publisher_.publish(batcher_.take());
    }
    if (batcher_.due(now)) publisher_.publish(batcher_.take());
    if (now >= next_calibration_poll_) {
      publisher_.poll_calibration();
      next_calibration_poll_ = now + std::chrono::milliseconds(100);
    }
    if (now >= next_status_) publish_status(now);
    if (o_.duration_s > 0 && now - started_ >= std::chrono::duration<double>(o_.duration_s)) return false;
    return source_alive;
  }

  void note_samples(Clock::time_point now) {
    if (!samples_.empty()) {
      total_samples_ += samples_.size();
      last_sample_ = now;
      next_silence_note_s_ = 5;
    } else if (std::chrono::duration<double>(now - last_sample_).count() > next_silence_note_s_) {
      log("no sample from " + source_.describe() + " for " + std::to_string(static_cast<int>(next_silence_note_s_)) +
          " s (" + (source_.healthy() ? "open; is the board sending, at this --baud?" : "not open") + "); " +
          summary(counters_));
      next_silence_note_s_ *= 2;
    }
  }

  void publish_status(Clock::time_point now) {
    const std::string error = source_.last_error();
    if (!error.empty()) last_error_ = error;
    const bool new_problems = counters_.problems() != problems_at_last_status_;
    problems_at_last_status_ = counters_.problems();
    publisher_.publish_status(!source_.healthy() || new_problems ? "degraded" : "running", last_error_);
    next_status_ += status_period_;
    if (next_status_ < now) next_status_ = now + status_period_;
  }

  const Options& o_;
  bridge::SampleSource& source_;
  bridge::SampleChecker& checker_;
  Publisher& publisher_;
  bridge::Counters& counters_;
  Batcher batcher_;
  std::vector<Sample> samples_;
  const Clock::duration status_period_ =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o_.status_period_s));
  const Clock::time_point started_ = Clock::now();
  Clock::time_point next_status_ = started_;
  Clock::time_point next_calibration_poll_ = started_;
  Clock::time_point last_sample_ = started_;
  double next_silence_note_s_ = 5;
  std::uint64_t problems_at_last_status_ = 0;
  std::uint64_t total_samples_ = 0;
  std::string last_error_;
};

// The end: status, the summary line, time for reliable readers, and the exit status: 1 when the
// calibrated stream was stopped or nothing was read.
int finish(const Options& o, const PublisherOptions& po, Publisher& publisher, const bridge::SampleSource& source,
           const bridge::Counters& counters, const Pump& pump) {
  publisher.publish_status("stopping", pump.last_error());
  log(std::string(components::g_stop ? "interrupted" : "finished") + "; " + summary(counters));
  if (po.reliable && !components::g_stop) components::sleep_while_running(o.linger_s);
  // Even after Ctrl-C: a writer deleted right after its last write may take that message with it.
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  // Raw data went out, but not the calibrated stream that was asked for: a script must not
  // take this run for a good one.
  if (publisher.calibrated_stopped()) {
    components::print_error(kProgram, "the calibrated stream was stopped by the |G| check (above); only raw data was published");
    return 1;
  }
  if (pump.total_samples() == 0) {
    // Ended having published nothing: say it, and do not report success.
    components::print_error(kProgram, "no sample read from " + source.describe() +
                                          (pump.last_error().empty() ? std::string() : " (" + pump.last_error() + ")"));
    return 1;
  }
  return 0;
}

int run(const Options& o) {
  const csv::Import import = checked_import(o);
  bridge::Counters counters;
  BadInputLog bad_input(o.max_logged_errors);
  bridge::SampleChecker checker(counters, o.limits);
  const std::unique_ptr<bridge::SampleSource> source = open_source(o, import, counters, checker, bad_input);
  const CalibrationModel file_model = calibration_from_file(o);

  components::install_stop_handler();
  auto connection = components::connect(o.transport, kProgram);
  PublisherOptions po = o.publish;
  if (o.no_calibration_topic) po.calibration_topic.clear();
  Publisher publisher(*connection.participant, po, counters, log);
  start_publishing(o, po, connection, *source, publisher, file_model);

  Pump pump(o, *source, checker, publisher, counters);
  pump.run();
  return finish(o, po, publisher, *source, counters, pump);
}

}  // namespace
}  // namespace plumb::bridge_component

int main(int argc, char** argv) {
  using namespace plumb::bridge_component;
  CLI::App app{"plumb-bridge: reads the sensor board (serial device, docs/protocol.md) or replays a sensor CSV, "
               "checks every sample, and publishes raw and calibrated sensor batches and its status over DDS"};
  app.name(kProgram);
  Options options;
  add_options(app, options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return plumb::components::exit_on_parse_error(app, e);
  }
  if (options.publish.binding.tool_id.empty()) {  // a usage error: an empty id would bind to nothing
    plumb::components::print_error(kProgram, "--tool-id must not be empty: coefficients bind to a tool id (docs/calibration.md)");
    return 2;
  }
  try {
    return run(options);
  } catch (const std::exception& e) {
    return plumb::components::exit_on_error(kProgram, e);
  }
}
