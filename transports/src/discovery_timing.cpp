#include "plumb/transport/discovery_timing.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "plumb/transport/transport.hpp"

namespace plumb::transport {

DiscoveryTiming discovery_timing() {
  DiscoveryTiming t;
  const char* text = std::getenv("PLUMB_DDS_LEASE_S");
  if (text == nullptr || *text == '\0') return t;
  char* end = nullptr;
  const double lease = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(lease >= 2 && lease <= 3600))
    throw Error("PLUMB_DDS_LEASE_S='" + std::string(text) + "' is not a lease in seconds between 2 and 3600");
  t.lease_s = lease;
  t.announce_s = std::min(t.announce_s, lease / 3);
  return t;
}

}  // namespace plumb::transport
