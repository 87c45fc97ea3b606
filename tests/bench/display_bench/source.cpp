// plumb-bench-display-source: publishes Attitude on plumb/attitude/bench at a steady rate, each
// stamped with the wall-clock time of its publication (window_end_ns), so that any receiver on
// this computer (plumb topic echo, a WebSocket client of plumb-display, the page in a browser)
// measures its latency from publication. Driven by display_bench.py.
#include <chrono>
#include <iostream>
#include <thread>

#include "plumb/components/cli.hpp"
#include "plumb/transport/topic_names.hpp"

int main(int argc, char** argv) {
  using namespace plumb;
  components::TransportOptions transport;
  double rate_hz = 20, seconds = 20;
  CLI::App app{"plumb-bench-display-source: wall-clock-stamped estimates on plumb/attitude/bench, for display_bench.py"};
  app.name("plumb-bench-display-source");
  components::add_transport_options(app, transport);
  app.add_option("--rate", rate_hz, "estimates a second")->capture_default_str()->check(CLI::Range(0.1, 10000.0));
  app.add_option("--seconds", seconds, "how long to publish")->capture_default_str();
  if (const int status = components::parse_command_line(app, argc, argv); status >= 0) return status;
  try {
    auto conn = components::connect(transport, "plumb-bench-display-source");
    const std::string topic = transport::topic_names::attitude("bench");
    auto writer = transport::make_writer<topics::Attitude>(*conn.participant, topic, transport::default_qos_for_topic(topic));
    components::install_stop_handler();
    topics::Attitude a;
    a.tool_id = "bench";
    a.estimator = "bench";
    a.flags = 7;
    const auto period = std::chrono::duration<double>(1.0 / rate_hz);
    const auto t0 = std::chrono::steady_clock::now();
    for (long i = 0; !components::g_stop && i < static_cast<long>(seconds * rate_hz); ++i) {
      std::this_thread::sleep_until(t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(period * i));
      a.inclination_deg = 10 + 0.001 * static_cast<double>(i % 1000);
      a.azimuth_deg = static_cast<double>(i % 360);
      a.samples_used = static_cast<std::uint32_t>(i);
      a.window_end_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
      writer.write(a);
    }
    components::sleep_while_running(0.5);  // reliable: the last ones acknowledged before the writer goes
    return 0;
  } catch (const std::exception& e) {
    return components::exit_on_error("plumb-bench-display-source", e);
  }
}
