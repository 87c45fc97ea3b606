#include "plumb/wits/tcp_sender.hpp"

#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <thread>

namespace plumb::wits {
namespace {

using SenderClock = std::chrono::steady_clock;

std::string sender_seconds_text(std::chrono::milliseconds d) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << static_cast<double>(d.count()) / 1000.0;
  return out.str();
}

}  // namespace

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

void close_when_sent(int fd) {
  for (int i = 0; i < 100; ++i) {
    int queued = 0;
    if (::ioctl(fd, TIOCOUTQ, &queued) != 0 || queued == 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::close(fd);
}

TcpSender::TcpSender(std::string host, int port) : host_(std::move(host)), port_(port) {}

TcpSender::~TcpSender() { close_socket(); }

std::string TcpSender::address() const { return host_ + ":" + std::to_string(port_); }

void TcpSender::close_socket() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

bool TcpSender::attempt(std::chrono::milliseconds handshake) {
  const std::string prefix = "cannot connect to " + address() + ": ";
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int rc = ::getaddrinfo(host_.c_str(), std::to_string(port_).c_str(), &hints, &found); rc != 0) {
    last_error_ = prefix + ::gai_strerror(rc);
    return false;
  }
  // Non-blocking, so that the handshake waits no longer than asked (a blocking connect to a host
  // that drops the packets waits for the kernel's SYN retries, about two minutes).
  const int fd = ::socket(found->ai_family, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd < 0) {
    last_error_ = prefix + std::strerror(errno);
    ::freeaddrinfo(found);
    return false;
  }
  int err = ::connect(fd, found->ai_addr, found->ai_addrlen) == 0 ? 0 : errno;
  ::freeaddrinfo(found);
  if (err == EINPROGRESS) {
    pollfd p{fd, POLLOUT, 0};
    int ready = 0;
    do ready = ::poll(&p, 1, static_cast<int>(handshake.count()));
    while (ready < 0 && errno == EINTR);
    if (ready == 0) {
      err = ETIMEDOUT;
    } else {
      socklen_t size = sizeof err;
      if (::getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &size) != 0) err = errno;
    }
  }
  if (err != 0) {
    last_error_ = prefix + std::strerror(err);
    ::close(fd);
    return false;
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // sends wait while the reader is slow
  fd_ = fd;
  last_error_.clear();
  return true;
}

bool TcpSender::connect(std::chrono::milliseconds wait, const std::function<bool()>& stop,
                        std::chrono::milliseconds retry) {
  using std::chrono::milliseconds;
  close_socket();
  const auto start = SenderClock::now();
  // Far deadlines (waiting "for ever") must not overflow the clock.
  const auto until = wait >= std::chrono::hours(24 * 365) ? SenderClock::time_point::max() : start + wait;
  int attempts = 0;
  for (;;) {
    const auto left = std::chrono::duration_cast<milliseconds>(until - SenderClock::now());
    if (attempt(std::clamp(left, milliseconds(200), milliseconds(2000)))) return true;
    ++attempts;
    const auto now = SenderClock::now();
    if ((stop && stop()) || now >= until) break;
    std::this_thread::sleep_for(std::min<SenderClock::duration>(retry, until - now));  // the last try at the deadline
  }
  if (attempts > 1)
    last_error_ += " (" + std::to_string(attempts) + " attempts in " +
                   sender_seconds_text(std::chrono::duration_cast<milliseconds>(SenderClock::now() - start)) + " s)";
  return false;
}

bool TcpSender::send(const std::string& bytes) {
  if (fd_ < 0) {
    last_error_ = "not connected to " + address();
    return false;
  }
  if (send_all(fd_, bytes)) return true;
  last_error_ = "the connection to " + address() + " was lost: " + std::strerror(errno);
  close_socket();
  return false;
}

void TcpSender::close_when_sent() {
  if (fd_ >= 0) wits::close_when_sent(fd_);
  fd_ = -1;
}

}  // namespace plumb::wits
