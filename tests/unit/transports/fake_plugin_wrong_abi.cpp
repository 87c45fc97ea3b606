// A transport plugin built against other interface headers: the loader must refuse it.
#include "plumb/transport/loader.hpp"

extern "C" __attribute__((visibility("default"))) const struct plumb_transport_plugin* plumb_transport_plugin() {
  static const struct ::plumb_transport_plugin plugin{"0000000000000000", nullptr};
  return &plugin;
}
