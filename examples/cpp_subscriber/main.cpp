// plumb-example-subscriber: prints the Attitude messages published on "plumb/attitude/example",
// over the DDS vendor chosen with --transport or $PLUMB_TRANSPORT. Copy it as a starting point.
#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include "plumb/transport/loader.hpp"
#include "plumb/transport/transport.hpp"

namespace {
std::atomic<bool> stop_requested{false};
void request_stop(int) { stop_requested = true; }
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Prints the Attitude messages published on plumb/attitude/example."};
  app.name("plumb-example-subscriber");
  std::string transport_name;
  int count = 0;
  double timeout_s = 0;
  plumb::transport::ParticipantOptions options;
  options.name = "plumb-example-subscriber";
  app.add_option("--transport", transport_name, "DDS vendor: fastdds or cyclonedds (default: $PLUMB_TRANSPORT, then cyclonedds)");
  app.add_option("--count", count, "exit after this many messages, 0 for no end")->check(CLI::NonNegativeNumber);
  app.add_option("--timeout", timeout_s, "give up (exit code 1) after this many seconds, 0 for never")->check(CLI::NonNegativeNumber);
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
    auto reader = plumb::transport::make_reader<plumb::topics::Attitude>(*participant, "plumb/attitude/example",
                                                                         plumb::transport::Qos::attitude());
    std::cout << "listening on plumb/attitude/example over " << transport->vendor_version() << std::endl;

    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    int received = 0;
    plumb::topics::Attitude attitude;
    // While nothing arrives, say so after 3, 6, 12... s: a silent wait looks like a hang.
    auto last_message = std::chrono::steady_clock::now();
    double next_note_s = 3;
    while (!stop_requested && (count == 0 || received < count)) {
      if (timeout_s > 0 && std::chrono::steady_clock::now() > deadline) {
        std::cerr << "plumb-example-subscriber: timed out after " << received << " message(s)" << std::endl;
        return 1;
      }
      // Short waits so that Ctrl-C and --timeout are noticed promptly.
      if (!reader.wait(std::chrono::milliseconds(200))) {
        const double silent_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - last_message).count();
        if (silent_s >= next_note_s) {
          next_note_s *= 2;
          std::cerr << "plumb-example-subscriber: nothing on plumb/attitude/example for " << static_cast<int>(silent_s)
                    << " s (" << reader.matched_writers() << " writer(s) matched; is plumb-example-publisher running"
                    << " on the same --domain?)" << std::endl;
        }
        continue;
      }
      last_message = std::chrono::steady_clock::now();
      next_note_s = 3;
      while ((count == 0 || received < count) && reader.take(attitude)) {
        ++received;
        std::cout << attitude.tool_id << " [" << attitude.estimator << "] inclination " << attitude.inclination_deg
                  << " deg, azimuth " << attitude.azimuth_deg << " deg, toolface " << attitude.gravity_toolface_deg
                  << " deg, window end " << attitude.window_end_ns << " ns" << std::endl;
      }
    }
  } catch (const std::invalid_argument& e) {  // a usage error, such as an unknown --transport name
    std::cerr << "plumb-example-subscriber: " << e.what() << std::endl;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "plumb-example-subscriber: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
