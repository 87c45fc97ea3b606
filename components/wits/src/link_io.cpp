#include "link_io.hpp"

#include <arpa/inet.h>

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace plumb::wits {

Link::ReadResult read_socket(int fd, std::uint8_t* buffer, std::size_t capacity, std::chrono::milliseconds timeout,
                             LinkCounters& counters, std::string& last) {
  pollfd p{fd, POLLIN, 0};
  const int ready = ::poll(&p, 1, static_cast<int>(timeout.count()));
  if (ready == 0 || (ready < 0 && errno == EINTR)) return {};
  if (ready > 0) {
    // Read even on POLLHUP: what the peer sent before it closed is still there.
    const ssize_t n = ::recv(fd, buffer, capacity, MSG_DONTWAIT);
    if (n > 0) {
      counters.bytes_read += static_cast<std::uint64_t>(n);
      return {static_cast<std::size_t>(n), Link::Event::Data};
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) return {};
    last = n == 0 ? "connection closed by the peer" : std::string("connection lost: ") + std::strerror(errno);
  } else {
    last = std::string("poll failed: ") + std::strerror(errno);
  }
  ++counters.disconnects;
  return {0, Link::Event::Closed};
}

void keep_alive(int fd) {
  const int on = 1, idle = 10, interval = 5, count = 3;
  ::setsockopt(fd, SOL_SOCKET, SO_KEEPALIVE, &on, sizeof on);
  ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPIDLE, &idle, sizeof idle);
  ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPINTVL, &interval, sizeof interval);
  ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPCNT, &count, sizeof count);
}

int parse_port(const std::string& text, const std::string& what) {
  const std::string bad = what + ": port '" + text + "' is not a number in 1-65535";
  try {
    std::size_t used = 0;
    const int port = std::stoi(text, &used);
    if (used != text.size() || port < 1 || port > 65535) throw std::invalid_argument(bad);
    return port;
  } catch (const std::logic_error&) {
    throw std::invalid_argument(bad);
  }
}

void split_host_port(const std::string& text, const std::string& what, std::string& host, int& port) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
    throw std::invalid_argument(what + ": expected HOST:PORT (e.g. 10.0.0.5:5000), got '" + text + "'");
  host = text.substr(0, colon);
  port = parse_port(text.substr(colon + 1), what);
}

void split_listen_address(const std::string& text, const std::string& what, std::string& address, int& port) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos) {
    address = "0.0.0.0";
    port = parse_port(text, what);
    return;
  }
  if (colon == 0 || colon + 1 == text.size())
    throw std::invalid_argument(what + ": expected [ADDRESS:]PORT (e.g. 5000 or 10.0.0.5:5000), got '" + text + "'");
  address = text.substr(0, colon);
  in_addr parsed{};
  if (::inet_pton(AF_INET, address.c_str(), &parsed) != 1)
    throw std::invalid_argument(what + ": '" + address + "' is not an IPv4 address of this computer (e.g. 0.0.0.0:" +
                                text.substr(colon + 1) + " for every interface)");
  port = parse_port(text.substr(colon + 1), what);
}

}  // namespace plumb::wits
