// plumb transports | plugins: what is installed, and whether it loads.
#include <iostream>

#include "commands.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/estimator/loader.hpp"
#include "plumb/transport/loader.hpp"

namespace plumb::cli {

void add_listing_commands(CLI::App& app) {
  auto* transports = app.add_subcommand("transports", "List the DDS transport plugins found, and which is selected");
  // --transport (and --domain, --interface) are accepted here as on every command, so that a line
  // copied from another command works: `plumb transports --transport fastdds` marks fastdds.
  static components::TransportOptions s_transport;
  components::add_transport_options(*transports, s_transport);
  transports->callback([] {
    const std::string selected = transport::resolve_transport_name(s_transport.transport);
    const auto found = transport::find_transports();
    if (found.empty()) {
      std::cerr << "plumb transports: no transport plugin found (set PLUMB_TRANSPORT_PATH?)" << std::endl;
      g_exit_code = 1;
    }
    bool selected_found = false;
    for (const auto& t : found) selected_found = selected_found || t.name == selected;
    if (!found.empty() && !selected_found)
      throw plugin::UnknownName(plugin::unknown_name_message(transport::kTransportPlugins, selected, found));
    for (const auto& t : found) {
      std::string version;
      try {
        version = transport::load_transport(t.name)->vendor_version();
      } catch (const std::exception& e) {
        version = std::string("cannot load: ") + e.what();
        g_exit_code = 1;
      }
      std::cout << (t.name == selected ? "* " : "  ") << t.name << "  " << version << "  " << t.path << '\n';
    }
    std::cout << "(* selected: --transport, else $PLUMB_TRANSPORT, else " << transport::kDefaultTransport << ")\n";
  });

  auto* plugins = app.add_subcommand("plugins", "List the estimator plugins found, with their parameters");
  static bool s_verbose = false;
  plugins->add_flag("-v,--verbose", s_verbose, "also list each plugin's parameters");
  plugins->callback([] {
    const auto found = estimator::find_plugins();
    if (found.empty()) {
      std::cerr << "plumb plugins: no estimator plugin found (set PLUMB_ESTIMATOR_PATH?)" << std::endl;
      g_exit_code = 1;
    }
    for (const auto& p : found) {
      if (!p.error.empty()) {
        std::cout << p.name << "  BROKEN: " << p.error << "  " << p.path << '\n';
        g_exit_code = 1;
        continue;
      }
      std::cout << p.name << "  " << p.description << "  " << p.path << '\n';
      if (!s_verbose) continue;
      const auto est = estimator::load_estimator(p.name);
      for (const auto& spec : est->info().parameters) {
        std::cout << "    " << spec.name << " (default " << spec.default_value << "): " << spec.description << '\n';
      }
    }
  });
}

}  // namespace plumb::cli
