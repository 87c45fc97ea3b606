#include "output.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
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
#include "plumb/wits/tcp_sender.hpp"

namespace plumb::wits_send {
namespace {

using namespace std::chrono_literals;

// plumb-wits-send is a rig that keeps trying until a reader listens (or it is stopped): it says
// so once, after the first attempt failed.
class TcpClientOutput final : public Output {
 public:
  TcpClientOutput(std::string host, int port) : sender_(std::move(host), port) {}
  ~TcpClientOutput() override { drop(); }
  bool write(const std::string& bytes) override {
    if (!sender_.is_open() && !connect_now()) return false;
    if (sender_.send(bytes)) return true;
    drop();
    return false;
  }
  void drop() override { sender_.close_when_sent(); }
  std::string describe() const override { return "TCP client to " + sender_.address(); }

 private:
  bool connect_now() {
    const auto stopped = [] { return components::g_stop.load(); };
    if (!sender_.connect(0ms, stopped)) {
      std::cout << kProgram << ": waiting for a WITS reader at " << sender_.address() << " (" << sender_.last_error()
                << ")" << std::endl;
      if (!sender_.connect(std::chrono::hours(24 * 365), stopped)) return false;
    }
    std::cout << kProgram << ": connected to " << sender_.address() << std::endl;
    return true;
  }

  wits::TcpSender sender_;
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
    if (wits::send_all(fd_, bytes)) return true;
    drop();
    return false;
  }
  void drop() override {
    if (fd_ >= 0) wits::close_when_sent(fd_);
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
