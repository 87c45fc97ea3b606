#include "domain_config.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <cctype>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::cyclonedds {

namespace {

bool is_ipv4_address(const std::string& text) {
  in_addr address{};
  return inet_pton(AF_INET, text.c_str(), &address) == 1;
}

// Interface names are short and plain ("eth0", "enp3s0", "wlan0.5"); anything else would have to
// be escaped into the XML, and is more likely a typo than a real interface.
bool is_plain_name(const std::string& text) {
  return !text.empty() && text.size() < 64 && std::all_of(text.begin(), text.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '.' || c == '-' || c == '_' || c == ':' || c == '@';
  });
}

// Parts common to both setups: no shared memory (iceoryx needs its own daemon and does not cross
// users), no tracing, UDP only.
constexpr const char* kCommon =
    "<SharedMemory><Enable>false</Enable></SharedMemory>"
    "<Tracing><Verbosity>none</Verbosity></Tracing>";

}  // namespace

std::string domain_config(const std::string& interface) {
  if (interface.empty()) {
    // Loopback has no MULTICAST flag on Linux, so discovery goes by unicast to the well-known
    // RTPS ports of participant indices 0..MaxAutoParticipantIndex on 127.0.0.1. Fast DDS uses the
    // same port mapping, so the two vendors find each other on one host.
    return std::string(
               "<CycloneDDS><Domain Id=\"any\">"
               "<General><Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
               "<AllowMulticast>false</AllowMulticast></General>"
               "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
               "<MaxAutoParticipantIndex>40</MaxAutoParticipantIndex>"
               "<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>") +
           kCommon + "</Domain></CycloneDDS>";
  }
  if (!is_plain_name(interface)) throw Error("invalid network interface '" + interface + "'");
  const std::string attribute = is_ipv4_address(interface) ? "address" : "name";
  return "<CycloneDDS><Domain Id=\"any\">"
         "<General><Interfaces><NetworkInterface " +
         attribute + "=\"" + interface +
         "\"/></Interfaces></General>"
         "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
         "<MaxAutoParticipantIndex>40</MaxAutoParticipantIndex></Discovery>" +
         kCommon + "</Domain></CycloneDDS>";
}

}  // namespace plumb::transport::cyclonedds
