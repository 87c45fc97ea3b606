#include "network_interface.hpp"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netinet/in.h>

#include <memory>
#include <string>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::fastdds {

std::string resolve_ipv4_interface(const std::string& name_or_address) {
  if (name_or_address.empty()) return kLoopbackAddress;
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) throw Error("cannot list the network interfaces of this host");
  std::unique_ptr<ifaddrs, decltype(&freeifaddrs)> owner(list, &freeifaddrs);
  std::string available;
  for (const ifaddrs* it = list; it != nullptr; it = it->ifa_next) {
    if (it->ifa_addr == nullptr || it->ifa_addr->sa_family != AF_INET) continue;
    char text[INET_ADDRSTRLEN] = {};
    const auto* address = reinterpret_cast<const sockaddr_in*>(it->ifa_addr);
    if (inet_ntop(AF_INET, &address->sin_addr, text, sizeof text) == nullptr) continue;
    if (name_or_address == it->ifa_name || name_or_address == text) return text;
    available += std::string(available.empty() ? "" : ", ") + it->ifa_name + " (" + text + ")";
  }
  throw Error("network interface '" + name_or_address + "' has no IPv4 address on this host; available: " + available);
}

bool is_loopback_address(const std::string& ipv4) { return ipv4.rfind("127.", 0) == 0; }

}  // namespace plumb::transport::fastdds
