// plumb transports: the DDS transport plugins found, which is selected, and whether each loads.
#include <iostream>
#include <memory>

#include "plugins/plugin_verbs.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/transport/loader.hpp"

namespace plumb::cli {
namespace {

int run_transports(const components::TransportOptions& options) {
  int status = 0;
  const std::string selected = transport::resolve_transport_name(options.transport);
  const auto found = transport::find_transports();
  if (found.empty()) {
    std::cerr << "plumb transports: no transport plugin found (set PLUMB_TRANSPORT_PATH?)" << std::endl;
    status = 1;
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
      status = 1;
    }
    std::cout << (t.name == selected ? "* " : "  ") << t.name << "  " << version << "  " << t.path << '\n';
  }
  std::cout << "(* selected: --transport, else $PLUMB_TRANSPORT, else " << transport::kDefaultTransport << ")\n";
  return status;
}

}  // namespace

void add_transports_verb(CLI::App& app, Verbs& verbs) {
  auto* transports = app.add_subcommand("transports", "List the DDS transport plugins found, and which is selected");
  // --transport (and --domain, --interface) are accepted here as on every command, so that a line
  // copied from another command works: `plumb transports --transport fastdds` marks fastdds.
  auto options = std::make_shared<components::TransportOptions>();
  components::add_transport_options(*transports, *options);
  verbs.add(transports, [options] { return run_transports(*options); });
}

}  // namespace plumb::cli
