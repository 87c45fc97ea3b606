// The TCP client link: connects to the rig's WITS server, reconnects with back-off.
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <thread>

#include "link_io.hpp"
#include "plumb/wits/link.hpp"

namespace plumb::wits {
namespace {

using Clock = std::chrono::steady_clock;

class TcpClient final : public Link {
 public:
  TcpClient(std::string host, int port, Backoff backoff)
      : host_(std::move(host)), port_(port), backoff_(backoff), wait_(backoff.min) {}
  ~TcpClient() override { close_socket(); }

  ReadResult read(std::uint8_t* buffer, std::size_t capacity, std::chrono::milliseconds timeout) override {
    if (fd_ < 0) {
      const auto now = Clock::now();
      if (now < next_attempt_) {
        std::this_thread::sleep_for(std::min<Clock::duration>(timeout, next_attempt_ - now));
        return {};
      }
      if (connect_now()) return {0, Event::Opened};
      next_attempt_ = Clock::now() + wait_;
      wait_ = std::min(wait_ * 2, backoff_.max);
      return {0, Event::OpenFailed};
    }
    const auto r = read_socket(fd_, buffer, capacity, timeout, c_, last_);
    if (r.event == Event::Closed) {
      close_socket();
      next_attempt_ = Clock::now() + wait_;
    }
    return r;
  }
  bool is_open() const override { return fd_ >= 0; }
  std::string describe() const override { return "TCP client to " + host_ + ":" + std::to_string(port_); }
  std::string last_event() const override { return last_; }
  const LinkCounters& counters() const override { return c_; }

 private:
  bool connect_now() {
    addrinfo hints{};
    hints.ai_family = AF_INET;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    if (const int rc = ::getaddrinfo(host_.c_str(), std::to_string(port_).c_str(), &hints, &found); rc != 0) {
      last_ = host_ + ": " + ::gai_strerror(rc);
      return false;
    }
    const int fd = ::socket(found->ai_family, SOCK_STREAM | SOCK_CLOEXEC, 0);
    const bool ok = fd >= 0 && ::connect(fd, found->ai_addr, found->ai_addrlen) == 0;
    const int err = errno;
    ::freeaddrinfo(found);
    if (!ok) {
      last_ = "cannot connect to " + host_ + ":" + std::to_string(port_) + ": " + std::strerror(err);
      if (fd >= 0) ::close(fd);
      return false;
    }
    keep_alive(fd);
    fd_ = fd;
    last_ = "connected to " + host_ + ":" + std::to_string(port_);
    ++c_.connects;
    if (c_.connects > 1) ++c_.reconnects;
    wait_ = backoff_.min;
    return true;
  }
  void close_socket() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

  std::string host_;
  int port_;
  Backoff backoff_;
  std::chrono::milliseconds wait_;
  Clock::time_point next_attempt_{};
  int fd_ = -1;
  LinkCounters c_;
  std::string last_;
};

}  // namespace

std::unique_ptr<Link> make_tcp_client(const std::string& host, int port, Backoff backoff) {
  return std::make_unique<TcpClient>(host, port, backoff);
}

}  // namespace plumb::wits
