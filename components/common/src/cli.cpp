#include "plumb/components/cli.hpp"

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "plumb/components/params_file.hpp"
#include "plumb/core/number.hpp"
#include "plumb/transport/security.hpp"

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
  app.add_option("--security", options.security,
                 "DDS Security: identity folder made by `plumb security create-identity` (default: $PLUMB_SECURITY, "
                 "else unsecured); refused, never ignored, when a check fails (docs/security.md)");
}

void add_param_option(CLI::App& app, std::vector<std::string>& params) {
  app.add_option("--param", params,
                 "plugin parameter [PLUGIN.]KEY=VALUE, repeatable: KEY=VALUE goes to every plugin that declares KEY, "
                 "PLUGIN.KEY=VALUE to that plugin only (see plumb plugins -v)");
  // Defined after --param: CLI11 runs the callbacks in that order, so the file's entries go in
  // front of the --param ones, which then replace them.
  app.add_option_function<std::vector<std::string>>(
         "--params-file",
         [&params](const std::vector<std::string>& files) {
           std::vector<std::string> from_files;
           for (const auto& file : files) {
             try {
               const auto entries = read_params_file(file);
               from_files.insert(from_files.end(), entries.begin(), entries.end());
             } catch (const std::invalid_argument& e) {
               throw CLI::ValidationError(e.what());
             }
           }
           params.insert(params.begin(), from_files.begin(), from_files.end());
         },
         "YAML file of plugin parameters, repeatable: a plugin's name, then its KEY: VALUE lines indented "
         "below it; read before --param, which overrides it (docs/estimators.md \"Parameters files\")")
      ->type_name("FILE.yaml");
}

Connection connect(const TransportOptions& options, const std::string& participant_name) {
  transport::ParticipantOptions p;
  p.name = participant_name;
  p.interface = options.interface.empty() ? env_or("PLUMB_INTERFACE", "") : options.interface;
  p.security = options.security.empty() ? env_or(transport::kSecurityEnv, "") : options.security;
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
  c.options = p;
  return c;
}

void sleep_while_running(double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!g_stop && std::chrono::steady_clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(20));
}

double parse_rate_option(const std::string& text) {
  const auto speed = parse_pace(text);
  if (!speed) throw std::invalid_argument("--rate: expected realtime, xN (N > 0 times faster) or max, got '" + text + "'");
  return *speed;
}

void install_stop_handler() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

void print_error(const std::string& program, const std::string& message) {
  std::cerr << program << ": " << message << std::endl;
}

int exit_on_parse_error(const CLI::App& app, const CLI::ParseError& error) {
  if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(error);  // --help
  std::string what = error.what();
  while (!what.empty() && (what.back() == '\n' || what.back() == ' ')) what.pop_back();
  for (auto& c : what)
    if (c == '\n') c = ' ';
  const std::string program = app.get_name().empty() ? "plumb" : app.get_name();
  print_error(program, what + " (see " + program + " --help)");
  return kUsageError;
}

int exit_on_error(const std::string& program, const std::exception& error) {
  print_error(program, error.what());
  return dynamic_cast<const std::invalid_argument*>(&error) != nullptr ? kUsageError : 1;
}

int parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return exit_on_parse_error(app, e);
  }
  return -1;
}

}  // namespace plumb::components
