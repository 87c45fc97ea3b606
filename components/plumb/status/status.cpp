// plumb status: every plumb component seen on the network, with its host and state, from the
// plumb/status topic each one publishes once a second (components::StatusReporter). What a field
// engineer runs on either computer to check the link.
#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <tuple>

#include "plumb/components/cli.hpp"
#include "plumb/transport/topic_names.hpp"
#include "verbs.hpp"

namespace plumb::cli {
namespace {

struct StatusOptions {
  components::TransportOptions transport;
  double wait_s = 3;  // two status periods and discovery
  bool counters = false;
};

struct Seen {
  topics::ComponentStatus last;
  int messages = 0;
};

// What to check when nobody answers: the usual reasons, in the order they happen in the field.
std::string nothing_seen(const transport::ParticipantOptions& p, const std::string& vendor, double wait_s) {
  std::ostringstream out;
  out << "plumb status: no plumb component seen within " << wait_s << " s on domain " << p.domain_id << " ("
      << vendor << ", " << (p.interface.empty() ? std::string("loopback only") : "interface " + p.interface)
      << "): check that the other computer uses the same --domain, that --interface names the network joining the "
         "two (it must pass multicast and UDP ports "
      << 7400 + 250 * p.domain_id << " and up), and that its components are running";
  return out.str();
}

// Under the component's row, indented, as many name=value pairs per line as fit 100 columns: what a
// field engineer reads to see where samples went (lost, refused, repeated) without a topic echo.
void print_counters(const topics::ComponentStatus& status) {
  if (status.counters.empty()) {
    std::cout << "    (no counters)\n";
    return;
  }
  std::string line = "   ";
  for (const auto& c : status.counters) {
    const std::string pair = " " + c.name + "=" + std::to_string(c.value);
    if (line.size() + pair.size() > 100) {
      std::cout << line << '\n';
      line = "   ";
    }
    line += pair;
  }
  std::cout << line << '\n';
}

int run_status(const StatusOptions& o) {
  auto conn = components::connect(o.transport, "plumb-status");
  auto reader = transport::make_reader<topics::ComponentStatus>(*conn.participant, transport::topic_names::kStatus,
                                                                 transport::default_qos_for_topic(transport::topic_names::kStatus));
  components::install_stop_handler();
  // By host, component and name: two estimator hosts on one computer, each with its --name, are two rows.
  std::map<std::tuple<std::string, std::string, std::string>, Seen> seen;
  const auto t0 = std::chrono::steady_clock::now();
  const auto until = t0 + std::chrono::duration<double>(o.wait_s);
  topics::ComponentStatus msg;
  while (!components::g_stop && std::chrono::steady_clock::now() < until) {
    reader.wait(std::chrono::milliseconds(100));
    while (reader.take(msg)) {
      auto& s = seen[{msg.host, msg.component, msg.name}];
      s.last = msg;
      ++s.messages;
    }
  }
  if (seen.empty()) {
    std::cerr << nothing_seen(conn.options, conn.transport->vendor_version(), o.wait_s) << std::endl;
    return 1;
  }
  // NAME: what the component was named (plumb-estimator --name: what plumb component and plumb
  // param call it), "-" for none.
  std::size_t name_width = 6;
  for (const auto& [key, s] : seen) name_width = std::max(name_width, std::get<2>(key).size() + 2);
  std::cout << std::left << std::setw(20) << "HOST" << std::setw(22) << "COMPONENT" << std::setw(10) << "STATE"
            << std::setw(static_cast<int>(name_width)) << "NAME" << "REPORTS  LAST ERROR\n";
  bool healthy = true;
  for (const auto& [key, s] : seen) {
    const auto& [host, component, name] = key;
    std::cout << std::setw(20) << host << std::setw(22) << component << std::setw(10) << s.last.state
              << std::setw(static_cast<int>(name_width)) << (name.empty() ? "-" : name) << std::setw(9) << s.messages
              << (s.last.last_error.empty() ? "-" : s.last.last_error) << '\n';
    if (o.counters) print_counters(s.last);
    healthy = healthy && s.last.state != "degraded" && s.last.state != "failed";
  }
  std::cout << seen.size() << " component(s) on domain " << conn.options.domain_id << std::endl;
  return healthy ? 0 : 1;
}

}  // namespace

void add_status_verb(CLI::App& app, Verbs& verbs) {
  auto* status = app.add_subcommand("status", "List every plumb component seen on the network, with its host, state and "
                                                "name (an estimator host's --name)");
  status->footer("Listens to plumb/status (each component reports once a second and keeps its last report for "
                 "monitors that start later: a running component answers at once). Exit 1 if nobody answered or "
                 "a component is degraded or failed.");
  auto o = std::make_shared<StatusOptions>();
  components::add_transport_options(*status, o->transport);
  status->add_option("--wait", o->wait_s, "seconds to listen")->capture_default_str()->check(CLI::PositiveNumber);
  status->add_flag("--counters", o->counters, "also print each component's counters (from its latest report)");
  verbs.add(status, [o] { return run_status(*o); });
}

}  // namespace plumb::cli
