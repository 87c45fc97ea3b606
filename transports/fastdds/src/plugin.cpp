// The plugin's only exported symbol (everything else is hidden): the loader checks abi_version and
// name, then calls create().
#include "fast_transport.hpp"
#include "plumb/transport/loader.hpp"

namespace {

plumb::transport::Transport* create_fast_transport() { return new plumb::transport::fastdds::FastTransport(); }

constexpr plumb_transport_plugin_v1 kPlugin{PLUMB_TRANSPORT_ABI_VERSION, "fastdds", &create_fast_transport};

}  // namespace

extern "C" __attribute__((visibility("default"))) const plumb_transport_plugin_v1* plumb_transport_plugin() {
  return &kPlugin;
}
