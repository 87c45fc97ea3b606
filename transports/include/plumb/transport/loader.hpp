// Loads a transport plugin by name. Plugins are shared libraries named
// libplumb_transport_<name>.so, found in $PLUMB_TRANSPORT_PATH (':'-separated) and then next to
// libplumb_transport.so. Each exports
//   extern "C" const plumb_transport_plugin_v1* plumb_transport_plugin();
// and is refused unless its abi_version matches ours.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "plumb/transport/transport.hpp"

extern "C" {
struct plumb_transport_plugin_v1 {
  unsigned abi_version;  // PLUMB_TRANSPORT_ABI_VERSION
  const char* name;
  plumb::transport::Transport* (*create)();
};
}

#define PLUMB_TRANSPORT_ABI_VERSION 1u

namespace plumb::transport {

inline constexpr const char* kDefaultTransport = "cyclonedds";
inline constexpr const char* kTransportEnv = "PLUMB_TRANSPORT";

struct FoundTransport {
  std::string name;
  std::string path;
};

// Every plugin library on the search path (loadable or not).
std::vector<FoundTransport> find_transports();

// The transport named `name`; an empty name means $PLUMB_TRANSPORT, then kDefaultTransport.
// Throws Error naming the transports found when the name is unknown or the library is broken.
// The returned object keeps its library loaded; so does every participant it creates.
std::shared_ptr<Transport> load_transport(const std::string& name = "");

// Resolves "" to $PLUMB_TRANSPORT or the default, without loading anything.
std::string resolve_transport_name(const std::string& name);

}  // namespace plumb::transport
