// Loads a transport plugin by name: libplumb_transport_<name>.so, found and checked by the plugin
// facility (plumb/plugin/library.hpp: search path, identity, ABI, lifetime). A plugin exports
//   extern "C" const plumb_transport_plugin* plumb_transport_plugin();
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "plumb/plugin/library.hpp"
#include "plumb/transport/abi.hpp"
#include "plumb/transport/transport.hpp"

extern "C" {
struct plumb_transport_plugin {
  const char* abi;  // PLUMB_TRANSPORT_ABI: first member, read by the plugin facility
  plumb::transport::Transport* (*create)();
};
}

// Defines the entry point of a transport plugin whose Transport class is default-constructible.
#define PLUMB_TRANSPORT_PLUGIN(CLASS)                                                                   \
  extern "C" __attribute__((visibility("default"))) const struct plumb_transport_plugin* plumb_transport_plugin() { \
    static const struct ::plumb_transport_plugin plugin{                                                       \
        PLUMB_TRANSPORT_ABI, []() -> plumb::transport::Transport* { return new CLASS(); }};             \
    return &plugin;                                                                                     \
  }

namespace plumb::transport {

inline constexpr const char* kDefaultTransport = "cyclonedds";
inline constexpr const char* kTransportEnv = "PLUMB_TRANSPORT";

extern const plugin::Kind kTransportPlugins;

// Every transport plugin on the search path (by file name; nothing is loaded).
std::vector<plugin::Found> find_transports();

// The transport named `name`; an empty name means $PLUMB_TRANSPORT, then kDefaultTransport.
// Throws Error (one line naming the file and the reason, or the transports found).
std::shared_ptr<Transport> load_transport(const std::string& name = "");

// Resolves "" to $PLUMB_TRANSPORT or the default, without loading anything.
std::string resolve_transport_name(const std::string& name);

}  // namespace plumb::transport
