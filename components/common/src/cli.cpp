#include "plumb/components/cli.hpp"

#include <csignal>
#include <cstdlib>
#include <iostream>

namespace plumb::components {

std::atomic<bool> g_stop{false};

namespace {
void on_signal(int) { g_stop = true; }

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : fallback;
}
}  // namespace

void add_transport_options(CLI::App& app, TransportOptions& options) {
  app.add_option("--transport", options.transport,
                 "DDS vendor plugin: cyclonedds or fastdds (default: $PLUMB_TRANSPORT, else cyclonedds)");
  app.add_option("--domain", options.domain_id, "DDS domain id 0..232 (default: $PLUMB_DOMAIN_ID, else 0)");
  app.add_option("--interface", options.interface,
                 "network interface name or IPv4 address to use (default: $PLUMB_INTERFACE, else loopback only)");
}

Connection connect(const TransportOptions& options, const std::string& participant_name) {
  transport::ParticipantOptions p;
  p.name = participant_name;
  p.interface = options.interface.empty() ? env_or("PLUMB_INTERFACE", "") : options.interface;
  if (options.domain_id >= 0) {
    p.domain_id = options.domain_id;
  } else {
    const std::string env = env_or("PLUMB_DOMAIN_ID", "0");
    try {
      std::size_t used = 0;
      p.domain_id = std::stoi(env, &used);
      if (used != env.size()) throw std::invalid_argument(env);
    } catch (const std::exception&) {
      throw transport::Error("PLUMB_DOMAIN_ID='" + env + "' is not a domain id (0..232)");
    }
  }
  if (p.domain_id < 0 || p.domain_id > 232) {
    throw transport::Error("domain id " + std::to_string(p.domain_id) + " is out of range (0..232)");
  }
  Connection c;
  c.transport = transport::load_transport(options.transport);
  c.participant = c.transport->create_participant(p);
  return c;
}

void install_stop_handler() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

void print_error(const std::string& program, const std::string& message) {
  std::cerr << program << ": " << message << std::endl;
}

}  // namespace plumb::components
