// plumb-display: the live display in a browser. Joins the DDS domain, reads every estimator's
// attitude (plumb/attitude/<estimator>), the survey stations (plumb/survey/<tool>), their clearance
// from offset wells (plumb/clearance) and every component's status (plumb/status), and serves a
// page that shows them live: dials, numbers with their sigma, history charts, rotation speed,
// stations, the nearest offset, status and counters. docs/display.md.
#include <chrono>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "addresses.hpp"
#include "attitude_difference.hpp"
#include "dds_feed.hpp"
#include "foxglove_feed.hpp"
#include "foxglove_hub.hpp"
#include "foxglove_server.hpp"
#include "hub.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/components/status_reporter.hpp"
#include "web_server.hpp"

namespace plumb::display_component {
namespace {

struct Options {
  components::TransportOptions transport;
  WebOptions web;
  FoxgloveServerOptions foxglove;
  std::size_t foxglove_queue = FoxgloveOptions{}.queue;
  bool no_foxglove = false;
  double max_rate = 30;   // frames per second and browser
  double history_s = 600;
  double duration_s = 0;  // 0: until Ctrl-C
};

int run(const Options& o) {
  if (o.max_rate <= 0) throw std::invalid_argument("--max-rate must be > 0 frames per second");
  if (o.history_s < 0) throw std::invalid_argument("--history must be >= 0 seconds");
  HubOptions hub_options;
  hub_options.min_gap = std::chrono::milliseconds(static_cast<long>(1000.0 / o.max_rate));
  hub_options.history_s = o.history_s;
  Hub hub(hub_options);
  std::optional<FoxgloveHub> foxglove_hub;
  if (!o.no_foxglove) {
    if (o.foxglove_queue == 0) throw std::invalid_argument("--foxglove-queue must be >= 1 message");
    FoxgloveOptions fo;
    fo.queue = o.foxglove_queue;
    foxglove_hub.emplace(fo);
  }
  auto conn = components::connect(o.transport, "plumb-display");
  // Two or more plugins of one tool: their differences, computed once, for the page and Foxglove.
  PluginDifferences differences(foxglove_hub ? &*foxglove_hub : nullptr);
  DdsFeed feed(*conn.participant, hub, differences);
  // The servers start after DDS. One whose port is taken is said, and the other serves alone (a
  // display that still shows something beats none on a rig); with neither, the program ends.
  std::vector<std::string> refusals;
  const auto refused = [&](const std::exception& e) { refusals.emplace_back(e.what()); };
  std::optional<WebServer> server;
  try {
    server.emplace(o.web, hub);
  } catch (const std::runtime_error& e) {
    refused(e);
  }
  std::optional<FoxgloveServer> foxglove_server;
  std::optional<FoxgloveFeed> foxglove_feed;
  if (foxglove_hub) {
    FoxgloveServerOptions fs = o.foxglove;
    fs.bind = o.web.bind;
    try {
      foxglove_server.emplace(fs, *foxglove_hub);
      foxglove_feed.emplace(*conn.participant, *foxglove_hub);
    } catch (const std::runtime_error& e) {
      refused(e);
    }
  }
  if (!server && !foxglove_server) throw std::runtime_error(refusals.front());
  std::string not_served;
  for (const std::string& r : refusals) {
    std::cerr << "plumb-display: " << r << "; serving the rest" << std::endl;
    not_served += (not_served.empty() ? "" : "; ") + r;
  }
  components::install_stop_handler();
  components::StatusReporter status(*conn.participant, "plumb-display");
  if (server) {
    // Addresses a browser can open: --bind 0.0.0.0 is every interface, not an address.
    const std::vector<std::string> addresses = page_addresses(o.web.bind, server->port());
    std::cout << "plumb-display: serving " << addresses.front() << " (domain " << conn.options.domain_id << ", "
              << conn.transport->name()
              << (o.web.bind == "127.0.0.1" ? "; this computer only: --bind 0.0.0.0 to serve the network" : "") << ")";
  } else {
    std::cout << "plumb-display: the page is not served (domain " << conn.options.domain_id << ", "
              << conn.transport->name() << ")";
  }
  if (foxglove_server) {
    std::cout << "; Foxglove on " << page_addresses(o.web.bind, foxglove_server->port(), "ws").front();
  } else {
    std::cout << (foxglove_hub ? "; Foxglove not served" : "; Foxglove off");
  }
  std::cout << std::endl;
  const auto say_every_interface = [&](const char* what, int port, const char* scheme) {
    const auto all = page_addresses(o.web.bind, port, scheme);
    if (all.size() < 2) return;
    std::cout << "plumb-display: " << what << "on every interface:";
    for (std::size_t i = 1; i < all.size(); ++i) std::cout << (i == 1 ? " " : ", ") << all[i];
    std::cout << std::endl;
  };
  if (server) say_every_interface("", server->port(), "http");
  if (foxglove_server) say_every_interface("Foxglove ", foxglove_server->port(), "ws");
  const auto t0 = std::chrono::steady_clock::now();
  while (!components::g_stop) {
    if (o.duration_s > 0 && std::chrono::steady_clock::now() - t0 >= std::chrono::duration<double>(o.duration_s)) break;
    feed.poll(std::chrono::milliseconds(50));
    if (status.due()) {
      const HubStats s = hub.stats();
      components::CounterList counters{{"browsers", s.browsers},
                                 {"browsers_total", s.browsers_total},
                                 {"attitudes", s.attitudes},
                                 {"statuses", s.statuses},
                                 {"stations", s.stations},
                                 {"clearances", s.clearances},
                                 {"depths", s.depths},
                                 {"topics", feed.topics()},
                                 {"frames_sent", server ? server->frames_sent() : 0},
                                 {"dropped", s.dropped}};
      if (foxglove_server) {
        const FoxgloveStats f = foxglove_hub->stats();
        counters.insert(counters.end(), {{"foxglove_clients", f.clients},
                                         {"foxglove_clients_total", f.clients_total},
                                         {"foxglove_channels", f.channels},
                                         {"foxglove_readers", foxglove_feed->readers()},
                                         {"foxglove_messages", f.messages},
                                         {"foxglove_dropped", f.dropped},
                                         {"foxglove_frames_sent", foxglove_server->frames_sent()},
                                         {"foxglove_refused", foxglove_server->refused()}});
      }
      // A server that could not listen keeps the display degraded, its reason on plumb/status.
      status.publish(not_served.empty() ? "running" : "degraded", counters, not_served);
    }
  }
  return 0;
}

}  // namespace
}  // namespace plumb::display_component

int main(int argc, char** argv) {
  using namespace plumb;
  display_component::Options o;
  CLI::App app{"plumb-display: the live display in a web browser: every estimator's inclination, azimuth and toolface "
               "(dials, numbers with sigma, history), rotation speed, survey stations, and every component's status"};
  app.name("plumb-display");
  components::add_transport_options(app, o.transport);
  app.add_option("--port", o.web.port, "TCP port of the page (0: any free port, printed at start)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  app.add_option("--bind", o.web.bind,
                 "address to listen on: 127.0.0.1 serves this computer only; 0.0.0.0 exposes the page to every "
                 "network the computer is on (no password, no encryption: see docs/display.md)")
      ->capture_default_str();
  app.add_option("--max-rate", o.max_rate, "at most this many updates a second to each browser")->capture_default_str();
  app.add_option("--history", o.history_s, "seconds of history a browser gets when it opens the page")->capture_default_str();
  app.add_option("--max-browsers", o.web.max_browsers, "browsers served at once (each holds a server thread); more are refused and their pages retry")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app.add_option("--web-root", o.web.web_root, "serve the page from this folder instead of the copy built in (to edit it)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--foxglove-port", o.foxglove.port,
                 "TCP port of the Foxglove WebSocket server (ws://HOST:PORT; 0: any free port, printed at start)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  app.add_flag("--no-foxglove", o.no_foxglove, "serve no Foxglove WebSocket (the page only)");
  app.add_option("--foxglove-queue", o.foxglove_queue,
                 "messages queued per Foxglove client; a slower client loses the oldest (counted: foxglove_dropped)")
      ->capture_default_str();
  app.add_option("--max-foxglove-clients", o.foxglove.max_clients, "Foxglove clients served at once; more are refused")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--duration", o.duration_s, "stop after this many seconds (0: until Ctrl-C)")->capture_default_str();
  app.footer("Open http://<computer>:<port>/ in any browser (phone, rig-floor screen); the page reconnects by itself.\n"
             "In Foxglove: Open connection, Foxglove WebSocket, ws://<computer>:8765 (--foxglove-port).");
  if (const int status = components::parse_command_line(app, argc, argv); status >= 0) return status;
  try {
    return display_component::run(o);
  } catch (const std::exception& e) {
    return components::exit_on_error("plumb-display", e);
  }
}
