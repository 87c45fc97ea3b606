#include "domain_config.hpp"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>

#include <algorithm>
#include <cctype>
#include <vector>

#include "plumb/transport/discovery_timing.hpp"
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

struct Ipv4Interface {
  std::string name;
  std::string address;
  bool loopback = false;
};

std::vector<Ipv4Interface> ipv4_interfaces() {
  std::vector<Ipv4Interface> result;
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) return result;
  for (const ifaddrs* i = list; i != nullptr; i = i->ifa_next) {
    if (i->ifa_addr == nullptr || i->ifa_addr->sa_family != AF_INET || !(i->ifa_flags & IFF_UP)) continue;
    char text[INET_ADDRSTRLEN] = {};
    inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in*>(i->ifa_addr)->sin_addr, text, sizeof text);
    result.push_back({i->ifa_name, text, (i->ifa_flags & IFF_LOOPBACK) != 0});
  }
  freeifaddrs(list);
  return result;
}

// The interface `wanted` names (by name or address); Error listing the candidates if none does.
// Checked here because Cyclone's own refusal is a bare "Error" after a log line of its own.
Ipv4Interface find_interface(const std::string& wanted) {
  const auto interfaces = ipv4_interfaces();
  for (const auto& i : interfaces) {
    if (i.name == wanted || i.address == wanted) return i;
  }
  std::string available;
  for (const auto& i : interfaces) available += (available.empty() ? "" : ", ") + i.name + " (" + i.address + ")";
  throw Error("network interface '" + wanted + "' has no IPv4 address on this host; available: " +
              (available.empty() ? std::string("none") : available));
}

// How long a participant that says nothing stays matched, and how often ours say they are alive
// (plumb/transport/discovery_timing.hpp). Cyclone's default lease (10 s) ended the match of every
// remote participant across a 10 s link outage: its reliable writers forgot their readers and what
// was written meanwhile was lost for good (attitude windows in the fault tests, docs/operations.md).
// Announcing every 3 s, as Fast DDS does, finds a peer again within seconds once an outage longer
// than the lease has ended a match (Cyclone's own default announces every lease - 2 s).
std::string discovery_timing_xml() {
  const DiscoveryTiming t = discovery_timing();
  const auto ms = [](double s) { return std::to_string(static_cast<long long>(s * 1000)) + " ms"; };
  return "<LeaseDuration>" + ms(t.lease_s) + "</LeaseDuration><SPDPInterval>" + ms(t.announce_s) + "</SPDPInterval>";
}

// Parts common to both setups: no shared memory (iceoryx needs its own daemon and does not cross
// users), no tracing, UDP only, and one receive thread for all sockets. With a thread per socket
// (Cyclone's default) shutting down wakes each thread with a datagram sent to itself: when the
// network interface is down that datagram never arrives and the component hung on SIGTERM for
// good (eclipse-cyclonedds/cyclonedds#1337; seen in the fault tests: plumb-sim with its link down).
// One thread waits on all sockets and a trigger of its own, and stops at once.
constexpr const char* kCommon =
    "<SharedMemory><Enable>false</Enable></SharedMemory>"
    "<Tracing><Verbosity>none</Verbosity></Tracing>"
    "<Internal><MultipleReceiveThreads>false</MultipleReceiveThreads></Internal>";

}  // namespace

std::string domain_config(const std::string& interface) {
  if (!interface.empty() && !is_plain_name(interface)) throw Error("invalid network interface '" + interface + "'");
  // Loopback named explicitly ("lo", "127.0.0.1") gets the loopback setup: it has no multicast.
  if (interface.empty() || find_interface(interface).loopback) {
    // Loopback has no MULTICAST flag on Linux, so discovery goes by unicast to the well-known
    // RTPS ports of participant indices 0..MaxAutoParticipantIndex on 127.0.0.1. Fast DDS uses the
    // same port mapping, so the two vendors find each other on one host.
    return std::string(
               "<CycloneDDS><Domain Id=\"any\">"
               "<General><Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
               "<AllowMulticast>false</AllowMulticast></General>"
               "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
               "<MaxAutoParticipantIndex>40</MaxAutoParticipantIndex>"
               "<Peers><Peer address=\"127.0.0.1\"/></Peers>") +
           discovery_timing_xml() + "</Discovery>" +
           kCommon + "</Domain></CycloneDDS>";
  }
  const std::string attribute = is_ipv4_address(interface) ? "address" : "name";
  return "<CycloneDDS><Domain Id=\"any\">"
         "<General><Interfaces><NetworkInterface " +
         attribute + "=\"" + interface +
         "\"/></Interfaces></General>"
         "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
         "<MaxAutoParticipantIndex>40</MaxAutoParticipantIndex>" +
         discovery_timing_xml() + "</Discovery>" +
         kCommon + "</Domain></CycloneDDS>";
}

}  // namespace plumb::transport::cyclonedds
