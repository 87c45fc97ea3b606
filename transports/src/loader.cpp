// Transport plugins through the plugin facility (plumb/plugin/library.hpp).
#include "plumb/transport/loader.hpp"

#include <cstdlib>

#include "vendor_library.hpp"

namespace plumb::transport {

const plugin::Kind kTransportPlugins{"transport", "libplumb_transport_", "PLUMB_TRANSPORT_PATH",
                                     "plumb_transport_plugin", PLUMB_TRANSPORT_ABI};

std::vector<plugin::Found> find_transports() { return plugin::find(kTransportPlugins); }

std::string resolve_transport_name(const std::string& name) {
  if (!name.empty()) return name;
  if (const char* env = std::getenv(kTransportEnv); env != nullptr && *env != '\0') return env;
  return kDefaultTransport;
}

std::shared_ptr<Transport> load_transport(const std::string& requested) {
  const std::string name = resolve_transport_name(requested);
  try {
    const plugin::Found found = plugin::locate(kTransportPlugins, name);
    const auto* entry = plugin::open<plumb_transport_plugin>(kTransportPlugins, found);
    if (entry->create == nullptr) throw plugin::Error(found.path, "has no create function");
    Transport* transport = entry->create();
    if (transport == nullptr) throw plugin::Error(found.path, "failed to start");
    return std::shared_ptr<Transport>(transport);
  } catch (const plugin::Error& e) {
    if (const auto missing = missing_vendor_library(e.reason)) {
      throw Error("transport '" + name + "' needs " + missing->library + ", which is missing or unreadable: install the " +
                  "Debian package " + missing->package + " (apt-get install " + missing->package + ")");
    }
    throw Error("transport '" + name + "' in " + e.what() + " (" + plugin::describe(kTransportPlugins, find_transports()) + ")");
  }
}

}  // namespace plumb::transport
