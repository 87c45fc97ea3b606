// The TCP server link: the rig (or its WITS distributor) connects to us. One connection at a
// time; a newer one replaces it, since a peer that reconnects knows better than we do that the
// old one is dead.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "link_io.hpp"
#include "plumb/wits/link.hpp"

namespace plumb::wits {
namespace {

std::string peer_name(const sockaddr_in& a) {
  char text[INET_ADDRSTRLEN] = {};
  ::inet_ntop(AF_INET, &a.sin_addr, text, sizeof text);
  return std::string(text) + ":" + std::to_string(ntohs(a.sin_port));
}

class TcpServer final : public Link {
 public:
  TcpServer(const std::string& address, int port) : address_(address.empty() ? "0.0.0.0" : address), port_(port) {
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    if (::inet_pton(AF_INET, address_.c_str(), &a.sin_addr) != 1)
      throw std::invalid_argument("'" + address_ + "' is not an IPv4 address");
    listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    const int on = 1;
    ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
    if (listen_fd_ < 0 || ::bind(listen_fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 ||
        ::listen(listen_fd_, 4) != 0) {
      const std::string why = std::strerror(errno);
      if (listen_fd_ >= 0) ::close(listen_fd_);
      throw std::runtime_error("cannot listen on " + address_ + ":" + std::to_string(port) + ": " + why);
    }
  }
  ~TcpServer() override {
    close_connection();
    ::close(listen_fd_);
  }

  ReadResult read(std::uint8_t* buffer, std::size_t capacity, std::chrono::milliseconds timeout) override {
    pollfd p[2] = {{listen_fd_, POLLIN, 0}, {fd_, POLLIN, 0}};
    const int ready = ::poll(p, fd_ >= 0 ? 2 : 1, static_cast<int>(timeout.count()));
    if (ready <= 0) return {};
    // Bytes of the current connection first: a peer that sent, closed and reconnected keeps its order.
    if (fd_ >= 0 && p[1].revents != 0) {
      const auto r = read_socket(fd_, buffer, capacity, std::chrono::milliseconds(0), c_, last_);
      if (r.event == Event::Closed) close_connection();
      if (r.event != Event::None) return r;
    }
    if (p[0].revents & POLLIN) {
      if (fd_ >= 0) {
        // The replaced connection's unread bytes end with it: the reader sees its stream end.
        close_connection();
        last_ = "a new connection replaces the current one";
        ++c_.disconnects;
        return {0, Event::Closed};
      }
      sockaddr_in peer{};
      socklen_t size = sizeof peer;
      const int fd = ::accept4(listen_fd_, reinterpret_cast<sockaddr*>(&peer), &size, SOCK_CLOEXEC);
      if (fd < 0) {
        last_ = std::string("accept failed: ") + std::strerror(errno);
        return {0, Event::OpenFailed};
      }
      keep_alive(fd);
      fd_ = fd;
      last_ = "connection from " + peer_name(peer);
      ++c_.connects;
      if (c_.connects > 1) ++c_.reconnects;
      return {0, Event::Opened};
    }
    return {};
  }
  bool is_open() const override { return fd_ >= 0; }
  std::string describe() const override { return "TCP server on " + address_ + ":" + std::to_string(port_); }
  std::string last_event() const override { return last_; }
  const LinkCounters& counters() const override { return c_; }

 private:
  void close_connection() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

  std::string address_;
  int port_;
  int listen_fd_ = -1;
  int fd_ = -1;
  LinkCounters c_;
  std::string last_;
};

}  // namespace

std::unique_ptr<Link> make_tcp_server(const std::string& address, int port) {
  return std::make_unique<TcpServer>(address, port);
}

}  // namespace plumb::wits
