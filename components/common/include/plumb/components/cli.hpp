// Command-line pieces every plumb executable shares: transport choice, domain, interface, logging.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "plumb/transport/loader.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::components {

struct TransportOptions {
  std::string transport;   // "" -> $PLUMB_TRANSPORT -> cyclonedds
  int domain_id = -1;      // -1 -> $PLUMB_DOMAIN_ID -> 0
  std::string interface;   // "" -> $PLUMB_INTERFACE -> loopback only
  std::string security;    // "" -> $PLUMB_SECURITY -> unsecured (an identity folder, docs/security.md)
};

// Adds --transport, --domain, --interface, --security to `app` (or a subcommand).
void add_transport_options(CLI::App& app, TransportOptions& options);

// --param [PLUGIN.]KEY=VALUE, the one parameter grammar of plumb estimate, plumb compare and
// plumb-estimator (estimators/plugins/api assignments.hpp does the parsing). No short form: -p is --plugin
// on plumb-estimator.
void add_param_option(CLI::App& app, std::vector<std::string>& params);

// A loaded transport and a participant on it; keeps the transport alive as long as it lives.
struct Connection {
  std::shared_ptr<transport::Transport> transport;
  std::unique_ptr<transport::Participant> participant;
  transport::ParticipantOptions options;  // as resolved from flags and environment (for messages)
};
// Throws transport::Error with a one-line message on failure.
Connection connect(const TransportOptions& options, const std::string& participant_name);

// Set by SIGINT/SIGTERM once install_stop_handler() ran; loops poll it to shut down cleanly.
extern std::atomic<bool> g_stop;
void install_stop_handler();
// Sleeps in small steps until the time is up or a stop was asked for, so Ctrl-C stays responsive.
// Used to linger after the last reliable write: the writer must live until readers acknowledge.
void sleep_while_running(double seconds);

// The --rate option of plumb-sim and plumb-bridge --replay (plumb::parse_pace's grammar): speed
// factor, 0 for as fast as possible. Throws std::invalid_argument with the one-line usage.
double parse_rate_option(const std::string& text);

// "plumb-estimator: <message>" on stderr (one line), for fatal errors before exit(1).
void print_error(const std::string& program, const std::string& message);

// Exit status of a usage error (a command line that cannot run), as every plumb executable uses.
inline constexpr int kUsageError = 2;

// What to do with a CLI11 parse error: --help and --version print and give 0; any other error is
// one stderr line "<program>: <what> (see <program> --help)" and kUsageError. CLI11's own exit()
// prints two lines and returns its internal codes (104..109), which scripts cannot rely on.
int exit_on_parse_error(const CLI::App& app, const CLI::ParseError& error);

// A fatal error caught in main(): one line, and the exit status: kUsageError for
// std::invalid_argument (an option or value that cannot work: the user must change the command),
// 1 for anything else (a file, the network, a device: the command was fine, the world was not).
int exit_on_error(const std::string& program, const std::exception& error);

// Parses the command line; returns -1 when the program should go on, else the exit status.
int parse_command_line(CLI::App& app, int argc, char** argv);

}  // namespace plumb::components
