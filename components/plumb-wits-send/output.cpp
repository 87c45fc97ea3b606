#include "output.hpp"

#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "plumb/bridge/pty.hpp"
#include "plumb/components/cli.hpp"

namespace plumb::wits_send {
namespace {

using namespace std::chrono_literals;

bool send_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::send(fd, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// Closes a socket once the peer has read everything sent (nothing left in the send queue), at
// most 2 s, so that a dropped connection loses no whole frame.
void close_when_sent(int fd) {
  for (int i = 0; i < 100; ++i) {
    int queued = 0;
    if (::ioctl(fd, TIOCOUTQ, &queued) != 0 || queued == 0) break;
    std::this_thread::sleep_for(20ms);
  }
  ::close(fd);
}

class TcpClientOutput final : public Output {
 public:
  TcpClientOutput(std::string host, int port) : host_(std::move(host)), port_(port) {}
  ~TcpClientOutput() override { drop(); }
  bool write(const std::string& bytes) override {
    if (fd_ < 0 && !connect_now()) return false;
    if (send_all(fd_, bytes)) return true;
    drop();
    return false;
  }
  void drop() override {
    if (fd_ >= 0) close_when_sent(fd_);
    fd_ = -1;
  }
  std::string describe() const override { return "TCP client to " + host_ + ":" + std::to_string(port_); }

 private:
  bool connect_now() {
    bool said = false;
    while (!components::g_stop) {
      addrinfo hints{};
      hints.ai_family = AF_INET;
      hints.ai_socktype = SOCK_STREAM;
      addrinfo* found = nullptr;
      if (::getaddrinfo(host_.c_str(), std::to_string(port_).c_str(), &hints, &found) == 0) {
        const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        const bool ok = ::connect(fd, found->ai_addr, found->ai_addrlen) == 0;
        ::freeaddrinfo(found);
        if (ok) {
          fd_ = fd;
          std::cout << kProgram << ": connected to " << host_ << ":" << port_ << std::endl;
          return true;
        }
        ::close(fd);
      }
      if (!said) std::cout << kProgram << ": waiting for a WITS reader at " << host_ << ":" << port_ << std::endl;
      said = true;
      std::this_thread::sleep_for(100ms);
    }
    return false;
  }

  std::string host_;
  int port_;
  int fd_ = -1;
};

class TcpServerOutput final : public Output {
 public:
  explicit TcpServerOutput(int port) : port_(port) {
    listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    const int on = 1;
    ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    a.sin_addr.s_addr = htonl(INADDR_ANY);
    if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(listen_fd_, 1) != 0)
      throw std::runtime_error("cannot listen on port " + std::to_string(port) + ": " + std::strerror(errno));
  }
  ~TcpServerOutput() override {
    drop();
    ::close(listen_fd_);
  }
  bool write(const std::string& bytes) override {
    if (fd_ < 0 && !accept_now()) return false;
    if (send_all(fd_, bytes)) return true;
    drop();
    return false;
  }
  void drop() override {
    if (fd_ >= 0) close_when_sent(fd_);
    fd_ = -1;
  }
  std::string describe() const override { return "TCP server on port " + std::to_string(port_); }

 private:
  bool accept_now() {
    std::cout << kProgram << ": waiting for a WITS reader to connect to port " << port_ << std::endl;
    while (!components::g_stop) {
      pollfd p{listen_fd_, POLLIN, 0};
      if (::poll(&p, 1, 100) <= 0) continue;
      fd_ = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
      if (fd_ >= 0) {
        std::cout << kProgram << ": a reader connected" << std::endl;
        return true;
      }
    }
    return false;
  }

  int port_;
  int listen_fd_ = -1;
  int fd_ = -1;
};

class PtyOutput final : public Output {
 public:
  explicit PtyOutput(std::string link) : link_(std::move(link)) { open(); }
  ~PtyOutput() override { bridge::remove_symlink(link_); }
  bool write(const std::string& bytes) override {
    if (!pty_) open();
    // Waits while the line is full: a reader that is a little late holds the rig up, loses nothing.
    return pty_->write_all(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), 10s);
  }
  void drop() override {
    if (!pty_) return;
    pty_->drain(10s);
    pty_.reset();  // closes both ends: the reader sees the device go
  }
  std::string describe() const override { return "pseudo-terminal linked at " + link_; }

 private:
  void open() {
    pty_ = std::make_unique<bridge::PseudoTerminal>();
    bridge::replace_symlink(pty_->slave_path(), link_);
  }

  std::string link_;
  std::unique_ptr<bridge::PseudoTerminal> pty_;
};

}  // namespace

std::unique_ptr<Output> make_tcp_client_output(const std::string& host, int port) {
  return std::make_unique<TcpClientOutput>(host, port);
}
std::unique_ptr<Output> make_tcp_server_output(int port) { return std::make_unique<TcpServerOutput>(port); }
std::unique_ptr<Output> make_pty_output(const std::string& link) { return std::make_unique<PtyOutput>(link); }

}  // namespace plumb::wits_send
