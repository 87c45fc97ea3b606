// A transport plugin built against another ABI version: the loader must refuse it.
#include "plumb/transport/loader.hpp"

extern "C" __attribute__((visibility("default"))) const plumb_transport_plugin_v1* plumb_transport_plugin() {
  static const plumb_transport_plugin_v1 plugin{PLUMB_TRANSPORT_ABI_VERSION + 1000u, "wrongabi", nullptr};
  return &plugin;
}
