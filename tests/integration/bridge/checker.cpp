// plumb-test-bridge-checker: subscribes to a sensor topic and checks that exactly the expected
// sequence numbers arrive (each once, in order), optionally that every sample is calibrated;
// records the bridge's last status counters. Exit 0 when all checks pass.
#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <thread>

#include <CLI/CLI.hpp>

#include "plumb/components/cli.hpp"
#include "plumb/transport/topic_names.hpp"

namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kProgram = "plumb-test-bridge-checker";

}  // namespace

int main(int argc, char** argv) {
  using namespace plumb;
  CLI::App app{"checks the sequence numbers arriving on a sensor topic and records plumb/status counters"};
  app.name(kProgram);
  components::TransportOptions transport_options;
  components::add_transport_options(app, transport_options);
  std::string topic = transport::topic_names::kSensorCalibrated;
  std::uint64_t count = 0, first = 0;
  double timeout_s = 60, settle_s = 0;
  bool reliable = false, any_start = false;
  std::string calibration_id, status_file, skip_list;
  app.add_option("--topic", topic, "sensor topic")->capture_default_str();
  app.add_option("--count", count, "samples expected")->required();
  app.add_option("--first", first, "first sequence number expected")->capture_default_str();
  app.add_option("--skip", skip_list, "comma-separated sequence numbers that must NOT arrive");
  app.add_option("--timeout", timeout_s, "give up after this many seconds")->capture_default_str();
  app.add_option("--settle", settle_s, "after the last sample, keep listening this long (extra samples fail)");
  app.add_flag("--reliable", reliable, "reliable reader (for a reliable bridge)");
  app.add_flag("--any-start", any_start, "the expected run starts at the first sequence number received");
  app.add_option("--calibration-id", calibration_id, "every batch must carry this calibration id and flag");
  app.add_option("--status-out", status_file, "write the last plumb/status counters here as name=value lines");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  std::set<std::uint64_t> skip;
  for (std::size_t at = 0; at < skip_list.size();) {
    const auto comma = skip_list.find(',', at);
    skip.insert(std::stoull(skip_list.substr(at, comma - at)));
    at = comma == std::string::npos ? skip_list.size() : comma + 1;
  }
  try {
    components::install_stop_handler();
    auto connection = components::connect(transport_options, kProgram);
    auto reader = transport::make_reader<topics::SensorBatch>(
        *connection.participant, topic, reliable ? transport::Qos::reliable_stream() : transport::Qos::sensor_stream());
    auto status_reader = transport::make_reader<topics::ComponentStatus>(
        *connection.participant, transport::topic_names::kStatus, transport::default_qos_for_topic(transport::topic_names::kStatus));
    std::vector<std::uint64_t> expected;
    for (std::uint64_t s = first; expected.size() < count; ++s)
      if (!skip.count(s)) expected.push_back(s);

    std::vector<std::uint64_t> got;
    std::size_t not_calibrated = 0, wrong_id = 0;
    std::optional<topics::ComponentStatus> last_status;
    const auto deadline = Clock::now() + std::chrono::duration<double>(timeout_s);
    std::optional<Clock::time_point> settle_until;
    topics::SensorBatch batch;
    topics::ComponentStatus status;
    while (!components::g_stop && Clock::now() < deadline) {
      if (settle_until && Clock::now() >= *settle_until) break;
      reader.wait(std::chrono::milliseconds(50));
      while (reader.take(batch)) {
        for (const auto& s : batch.samples) {
          got.push_back(s.seq);
          if (!calibration_id.empty() && !(s.flags & topics::SAMPLE_CALIBRATED)) ++not_calibrated;
        }
        if (!calibration_id.empty() && batch.calibration_id != calibration_id) ++wrong_id;
      }
      while (status_reader.take(status))
        if (status.component == "plumb-bridge") last_status = status;
      if (got.size() >= count && !settle_until) settle_until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(settle_s));
    }
    // The bridge's final status comes after its last batch.
    const auto status_deadline = Clock::now() + std::chrono::seconds(10);
    while (!status_file.empty() && Clock::now() < status_deadline && (!last_status || last_status->state != "stopping")) {
      status_reader.wait(std::chrono::milliseconds(50));
      while (status_reader.take(status))
        if (status.component == "plumb-bridge") last_status = status;
    }
    if (!status_file.empty()) {
      std::ofstream out(status_file);
      if (last_status) {
        out << "state=" << last_status->state << "\n";
        for (const auto& c : last_status->counters) out << c.name << "=" << c.value << "\n";
        out << "last_error=" << last_status->last_error << "\n";
      }
    }
    if (any_start && !got.empty()) {
      // A stream joined midway goes on after the window checked.
      if (got.size() > count) got.resize(count);
      expected.clear();
      for (std::uint64_t s = got.front(); expected.size() < count; ++s)
        if (!skip.count(s)) expected.push_back(s);
    }
    int failures = 0;
    if (got != expected) {
      ++failures;
      std::size_t i = 0;
      while (i < got.size() && i < expected.size() && got[i] == expected[i]) ++i;
      std::cerr << kProgram << ": received " << got.size() << " samples, expected " << expected.size()
                << "; first difference at index " << i << " (got "
                << (i < got.size() ? std::to_string(got[i]) : std::string("nothing")) << ", expected "
                << (i < expected.size() ? std::to_string(expected[i]) : std::string("nothing")) << ")" << std::endl;
    }
    if (not_calibrated || wrong_id) {
      ++failures;
      std::cerr << kProgram << ": " << not_calibrated << " samples without the calibrated flag, " << wrong_id
                << " batches without calibration id '" << calibration_id << "'" << std::endl;
    }
    std::cout << kProgram << ": " << got.size() << " samples on " << topic << (failures ? ": FAILED" : ": ok")
              << std::endl;
    return failures ? 1 : 0;
  } catch (const std::exception& e) {
    components::print_error(kProgram, e.what());
    return 1;
  }
}
