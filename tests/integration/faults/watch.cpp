// plumb-test-faults-watch: the fault tests' observer. It writes one line per event, stamped with
// the wall clock (seconds since the epoch, as `date +%s.%N` gives the test script), so that a
// script can set what it did (killed, restarted, link down) against what the system showed:
//   attitude T START_NS END_NS SAMPLES FLAGS      every message on --attitude
//   sensor_first T SEQ | sensor_gap T EXPECTED GOT | sensor_back T EXPECTED GOT
//   sensor_resume T SEQ SILENT_S                  a batch after at least 0.5 s of silence
//   batch T FIRST_SEQ LAST_SEQ                    every sensor batch (with --batches)
//   status T COMPONENT STATE name=value ...       every plumb/status message
//   calibration T CALIBRATION_ID                  every plumb/calibration message
//   summary samples=N gaps=G lost=L backwards=B attitude=A   at the end
// It never judges: tests/integration/faults/check_faults.py does.
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "plumb/components/cli.hpp"
#include "plumb/transport/topic_names.hpp"

namespace {

constexpr const char* kProgram = "plumb-test-faults-watch";
using Clock = std::chrono::steady_clock;

double wall() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace plumb;
  CLI::App app{"logs attitude, sensor sequence gaps, plumb/status and plumb/calibration with wall-clock stamps"};
  app.name(kProgram);
  components::TransportOptions transport_options;
  components::add_transport_options(app, transport_options);
  std::string attitude_topic, sensor_topic;
  bool reliable_sensor = false, calibration = false, every_batch = false;
  double duration_s = 0;
  app.add_option("--attitude", attitude_topic, "attitude topic to log (reliable)");
  app.add_option("--sensor", sensor_topic, "sensor topic whose sequence numbers to follow");
  app.add_flag("--reliable", reliable_sensor, "reliable sensor reader");
  app.add_flag("--batches", every_batch, "log every sensor batch's first and last sequence number");
  app.add_flag("--calibration", calibration, "log plumb/calibration (transient-local: late joiners get it)");
  app.add_option("--duration", duration_s, "stop after this many seconds (0: at SIGINT/SIGTERM)");
  if (const int status = components::parse_command_line(app, argc, argv); status >= 0) return status;
  try {
    components::install_stop_handler();
    auto connection = components::connect(transport_options, kProgram);
    auto& participant = *connection.participant;
    std::optional<transport::Reader<topics::Attitude>> attitude;
    if (!attitude_topic.empty())
      attitude.emplace(transport::make_reader<topics::Attitude>(participant, attitude_topic, transport::Qos::attitude()));
    std::optional<transport::Reader<topics::SensorBatch>> sensor;
    if (!sensor_topic.empty())
      sensor.emplace(transport::make_reader<topics::SensorBatch>(
          participant, sensor_topic, reliable_sensor ? transport::Qos::reliable_stream() : transport::Qos::sensor_stream()));
    auto status = transport::make_reader<topics::ComponentStatus>(participant, transport::topic_names::kStatus,
                                                                   transport::default_qos_for_topic(transport::topic_names::kStatus));
    std::optional<transport::Reader<topics::CalibrationCoefficients>> coefficients;
    if (calibration)
      coefficients.emplace(transport::make_reader<topics::CalibrationCoefficients>(
          participant, transport::topic_names::kCalibration, transport::Qos::calibration()));

    std::printf("watching %.3f\n", wall());
    std::fflush(stdout);
    std::uint64_t samples = 0, gaps = 0, lost = 0, backwards = 0, attitudes = 0;
    std::optional<std::uint64_t> next_seq;
    auto last_batch = Clock::now();
    const auto t0 = Clock::now();
    topics::Attitude a;
    topics::SensorBatch batch;
    topics::ComponentStatus s;
    topics::CalibrationCoefficients c;
    while (!components::g_stop &&
           (duration_s <= 0 || std::chrono::duration<double>(Clock::now() - t0).count() < duration_s)) {
      if (sensor) sensor->wait(std::chrono::milliseconds(20));
      else status.wait(std::chrono::milliseconds(20));
      while (attitude && attitude->take(a)) {
        ++attitudes;
        std::printf("attitude %.3f %lld %lld %u %u\n", wall(), static_cast<long long>(a.window_start_ns),
                    static_cast<long long>(a.window_end_ns), a.samples_used, a.flags);
      }
      while (sensor && sensor->take(batch)) {
        const double silent = std::chrono::duration<double>(Clock::now() - last_batch).count();
        last_batch = Clock::now();
        if (batch.samples.empty()) continue;
        if (every_batch)
          std::printf("batch %.3f %llu %llu\n", wall(), static_cast<unsigned long long>(batch.samples.front().seq),
                      static_cast<unsigned long long>(batch.samples.back().seq));
        if (next_seq && silent >= 0.5)
          std::printf("sensor_resume %.3f %llu %.3f\n", wall(), static_cast<unsigned long long>(batch.samples.front().seq), silent);
        for (const auto& m : batch.samples) {
          if (!next_seq) {
            std::printf("sensor_first %.3f %llu\n", wall(), static_cast<unsigned long long>(m.seq));
          } else if (m.seq > *next_seq) {
            ++gaps;
            lost += m.seq - *next_seq;
            std::printf("sensor_gap %.3f %llu %llu\n", wall(), static_cast<unsigned long long>(*next_seq),
                        static_cast<unsigned long long>(m.seq));
          } else if (m.seq < *next_seq) {
            ++backwards;
            std::printf("sensor_back %.3f %llu %llu\n", wall(), static_cast<unsigned long long>(*next_seq),
                        static_cast<unsigned long long>(m.seq));
          }
          next_seq = m.seq + 1;
          ++samples;
        }
      }
      while (status.take(s)) {
        std::printf("status %.3f %s %s", wall(), s.component.c_str(), s.state.c_str());
        for (const auto& counter : s.counters)
          std::printf(" %s=%llu", counter.name.c_str(), static_cast<unsigned long long>(counter.value));
        std::printf("\n");
      }
      while (coefficients && coefficients->take(c)) std::printf("calibration %.3f %s\n", wall(), c.calibration_id.c_str());
      std::fflush(stdout);
    }
    std::printf("summary samples=%llu gaps=%llu lost=%llu backwards=%llu attitude=%llu\n",
                static_cast<unsigned long long>(samples), static_cast<unsigned long long>(gaps),
                static_cast<unsigned long long>(lost), static_cast<unsigned long long>(backwards),
                static_cast<unsigned long long>(attitudes));
    return 0;
  } catch (const std::exception& e) {
    components::print_error(kProgram, e.what());
    return 1;
  }
}
