// plumb-example-publisher: publishes one Attitude message a second on "plumb/attitude/example",
// over the DDS vendor chosen with --transport or $PLUMB_TRANSPORT. Copy it as a starting point.
#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "plumb/transport/loader.hpp"
#include "plumb/transport/transport.hpp"

namespace {
std::atomic<bool> stop_requested{false};
void request_stop(int) { stop_requested = true; }
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Publishes an Attitude message on plumb/attitude/example once a second."};
  app.name("plumb-example-publisher");
  std::string transport_name;
  int count = 10;
  plumb::transport::ParticipantOptions options;
  options.name = "plumb-example-publisher";
  app.add_option("--transport", transport_name, "DDS vendor: fastdds or cyclonedds (default: $PLUMB_TRANSPORT, then cyclonedds)");
  app.add_option("--count", count, "messages to publish, 0 for no end")->check(CLI::NonNegativeNumber);
  // The same environment as plumb's executables; the options below override it.
  if (const char* env = std::getenv("PLUMB_DOMAIN_ID"); env && *env) {
    try {
      options.domain_id = std::stoi(env);
    } catch (const std::exception&) {
      std::cerr << app.get_name() << ": PLUMB_DOMAIN_ID='" << env << "' is not a domain id (0..232)" << std::endl;
      return 2;
    }
  }
  if (const char* env = std::getenv("PLUMB_INTERFACE"); env && *env) options.interface = env;
  app.add_option("--domain", options.domain_id, "DDS domain id (default: $PLUMB_DOMAIN_ID, then 0)")->check(CLI::Range(0, 232));
  app.add_option("--interface", options.interface,
                 "network interface (name or IPv4 address); default: $PLUMB_INTERFACE, then loopback only");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::cerr << app.get_name() << ": " << e.what() << " (see --help)" << std::endl;  // one line, status 2
    return 2;
  }

  std::signal(SIGINT, request_stop);
  std::signal(SIGTERM, request_stop);
  try {
    auto transport = plumb::transport::load_transport(transport_name);
    auto participant = transport->create_participant(options);
    auto writer = plumb::transport::make_writer<plumb::topics::Attitude>(*participant, "plumb/attitude/example",
                                                                         plumb::transport::Qos::attitude());
    std::cout << "publishing on plumb/attitude/example over " << transport->vendor_version() << std::endl;
    // Discovery takes a moment: give a subscriber that is already running up to 2 s to be found, so
    // that it gets the first message too (messages written before that are not kept for it).
    const auto discovery_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (writer.matched_readers() == 0 && !stop_requested && std::chrono::steady_clock::now() < discovery_deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }

    plumb::topics::Attitude attitude;
    attitude.tool_id = "example-tool";
    attitude.estimator = "example";
    attitude.flags = plumb::topics::ATTITUDE_VALID | plumb::topics::ATTITUDE_AZIMUTH_VALID |
                     plumb::topics::ATTITUDE_TOOLFACE_VALID;
    auto next = std::chrono::steady_clock::now();
    for (int i = 0; (count == 0 || i < count) && !stop_requested; ++i) {
      const auto now_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                              std::chrono::system_clock::now().time_since_epoch()).count();
      attitude.window_start_ns = now_ns - 1'000'000'000;
      attitude.window_end_ns = now_ns;
      attitude.inclination_deg = 30.0;
      attitude.azimuth_deg = 120.0;
      attitude.gravity_toolface_deg = (i * 36) % 360;  // the tool turns 36 degrees a second
      attitude.samples_used = 100;
      writer.write(attitude);
      std::cout << "sent #" << i << " toolface " << attitude.gravity_toolface_deg << " deg, "
                << writer.matched_readers() << " reader(s)" << std::endl;
      next += std::chrono::seconds(1);
      while (!stop_requested && std::chrono::steady_clock::now() < next) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  } catch (const std::invalid_argument& e) {  // a usage error, such as an unknown --transport name
    std::cerr << "plumb-example-publisher: " << e.what() << std::endl;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "plumb-example-publisher: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
