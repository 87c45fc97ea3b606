// A listening TCP socket on 127.0.0.1 for the tests of WITS links (the wits library's sender and
// plumb-sim's rig feed): real sockets, never a network beyond this computer.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>

namespace plumb::test {

// Binds 127.0.0.1:`port` (0: any free port, written back) and listens; -1 when it cannot.
inline int loopback_listen(int& port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  const int on = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(fd, 4) != 0) {
    ::close(fd);
    return -1;
  }
  socklen_t size = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &size);
  port = ntohs(a.sin_port);
  return fd;
}

// A port nobody listens on: one that was free a moment ago.
inline int loopback_closed_port() {
  int port = 0;
  ::close(loopback_listen(port));
  return port;
}

}  // namespace plumb::test
