#include "addresses.hpp"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>

namespace plumb::display_component {

std::vector<std::string> page_addresses(const std::string& bind, int port, const std::string& scheme) {
  const auto url = [port, &scheme](const std::string& host) { return scheme + "://" + host + ":" + std::to_string(port) + "/"; };
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

std::string listen_failure(const std::string& address, int port, const std::string& port_option) {
  in_addr ip{};
  if (::inet_pton(AF_INET, address.c_str(), &ip) != 1) return "'" + address + "' is not an IPv4 address (see --bind)";
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return std::strerror(errno);
  const int on = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);  // as civetweb does
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<std::uint16_t>(port));
  sa.sin_addr = ip;
  std::string why;
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&sa), sizeof sa) != 0) {
    const int e = errno;
    why = std::strerror(e);
    if (e == EADDRINUSE) why += " (another program serves this port: choose another " + port_option + ")";
    if (e == EADDRNOTAVAIL) why += " (not an address of this computer: see --bind)";
    if (e == EACCES) why += " (ports below 1024 need root: choose another " + port_option + ")";
  }
  ::close(fd);
  return why;
}

}  // namespace plumb::display_component
