#include "addresses.hpp"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>
#include <unistd.h>

#include <algorithm>

namespace plumb::display_component {

std::vector<std::string> page_addresses(const std::string& bind, int port) {
  const auto url = [port](const std::string& host) { return "http://" + host + ":" + std::to_string(port) + "/"; };
  if (!bind.empty() && bind != "0.0.0.0" && bind != "::") return {url(bind)};
  std::vector<std::string> out{url("127.0.0.1")};
  const auto add = [&](const std::string& host) {
    if (!host.empty() && std::find(out.begin(), out.end(), url(host)) == out.end()) out.push_back(url(host));
  };
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) == 0) add(name);
  ifaddrs* list = nullptr;
  if (::getifaddrs(&list) == 0) {
    for (const ifaddrs* i = list; i != nullptr; i = i->ifa_next) {
      if (i->ifa_addr == nullptr || i->ifa_addr->sa_family != AF_INET) continue;
      if ((i->ifa_flags & IFF_UP) == 0 || (i->ifa_flags & IFF_LOOPBACK) != 0) continue;
      char text[INET_ADDRSTRLEN] = {};
      const auto* in = reinterpret_cast<const sockaddr_in*>(i->ifa_addr);
      if (::inet_ntop(AF_INET, &in->sin_addr, text, sizeof text) != nullptr) add(text);
    }
    ::freeifaddrs(list);
  }
  return out;
}

}  // namespace plumb::display_component
