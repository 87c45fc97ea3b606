// Command-line pieces every plumb executable shares: transport choice, domain, interface, logging.
#pragma once

#include <atomic>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "plumb/transport/loader.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::components {

struct TransportOptions {
  std::string transport;   // "" -> $PLUMB_TRANSPORT -> cyclonedds
  int domain_id = -1;      // -1 -> $PLUMB_DOMAIN_ID -> 0
  std::string interface;   // "" -> $PLUMB_INTERFACE -> loopback only
};

// Adds --transport, --domain, --interface to `app` (or a subcommand).
void add_transport_options(CLI::App& app, TransportOptions& options);

// A loaded transport and a participant on it; keeps the transport alive as long as it lives.
struct Connection {
  std::shared_ptr<transport::Transport> transport;
  std::unique_ptr<transport::Participant> participant;
};
// Throws transport::Error with a one-line message on failure.
Connection connect(const TransportOptions& options, const std::string& participant_name);

// Set by SIGINT/SIGTERM once install_stop_handler() ran; loops poll it to shut down cleanly.
extern std::atomic<bool> g_stop;
void install_stop_handler();

// "plumb-estimator: <message>" on stderr (one line), for fatal errors before exit(1).
void print_error(const std::string& program, const std::string& message);

}  // namespace plumb::components
