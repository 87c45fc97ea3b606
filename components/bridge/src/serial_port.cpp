#include "plumb/bridge/serial_port.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <utility>

namespace plumb::bridge {
namespace {

struct BaudRate {
  int rate;
  speed_t constant;
};
constexpr BaudRate kRates[] = {
    {50, B50},         {75, B75},         {110, B110},         {134, B134},         {150, B150},
    {200, B200},       {300, B300},       {600, B600},         {1200, B1200},       {1800, B1800},
    {2400, B2400},     {4800, B4800},     {9600, B9600},       {19200, B19200},     {38400, B38400},
    {57600, B57600},   {115200, B115200}, {230400, B230400},   {460800, B460800},   {500000, B500000},
    {576000, B576000}, {921600, B921600}, {1000000, B1000000}, {1152000, B1152000}, {1500000, B1500000},
    {2000000, B2000000}, {2500000, B2500000}, {3000000, B3000000}, {3500000, B3500000}, {4000000, B4000000},
};

std::string errno_text(int err) { return std::strerror(err); }

}  // namespace

std::optional<unsigned> baud_constant(int baud) {
  for (const auto& r : kRates) {
    if (r.rate == baud) return static_cast<unsigned>(r.constant);
  }
  return std::nullopt;
}

std::string standard_baud_rates() {
  std::string s;
  for (const auto& r : kRates) s += (s.empty() ? "" : ", ") + std::to_string(r.rate);
  return s;
}

SerialPort::SerialPort(SerialOptions options, Counters& counters)
    : options_(std::move(options)), c_(counters), backoff_(options_.backoff_min) {
  const auto speed = baud_constant(options_.baud);
  if (!speed) {
    throw std::invalid_argument("baud rate " + std::to_string(options_.baud) +
                                " is not a standard rate (" + standard_baud_rates() + ")");
  }
  speed_ = *speed;
}

SerialPort::~SerialPort() { close(); }

void SerialPort::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void SerialPort::fail(const std::string& what, bool count_as_read_error) {
  last_error_ = options_.path + ": " + what;
  if (count_as_read_error) ++c_.read_errors;
}

bool SerialPort::try_open() {
  const int fd = ::open(options_.path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    fail("cannot open: " + errno_text(errno), false);
    return false;
  }
  termios tio{};
  if (::tcgetattr(fd, &tio) != 0) {
    fail("not a terminal device: " + errno_text(errno), false);
    ::close(fd);
    return false;
  }
  ::cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  // VMIN 1: with O_NONBLOCK an empty line reads as EAGAIN, so a read of 0 bytes really means
  // end of file (with VMIN 0 the tty driver returns 0 for "no data" too).
  tio.c_cc[VMIN] = 1;
  tio.c_cc[VTIME] = 0;
  ::cfsetispeed(&tio, static_cast<speed_t>(speed_));
  ::cfsetospeed(&tio, static_cast<speed_t>(speed_));
  if (::tcsetattr(fd, TCSANOW, &tio) != 0) {
    fail("cannot set raw mode at " + std::to_string(options_.baud) + " baud: " + errno_text(errno), false);
    ::close(fd);
    return false;
  }
  fd_ = fd;
  ++c_.opens;
  if (ever_opened_) ++c_.reopens;
  ever_opened_ = true;
  backoff_ = options_.backoff_min;
  return true;
}

SerialPort::ReadResult SerialPort::read(std::uint8_t* buffer, std::size_t capacity, std::chrono::milliseconds timeout) {
  using clock = std::chrono::steady_clock;
  if (fd_ < 0) {
    const auto now = clock::now();
    if (now < next_attempt_) {
      std::this_thread::sleep_for(std::min<clock::duration>(timeout, next_attempt_ - now));
      return {};
    }
    if (try_open()) return {0, Event::Opened};
    // Exponential back-off, capped: a missing device is retried forever without spinning.
    next_attempt_ = clock::now() + backoff_;
    backoff_ = std::min(backoff_ * 2, options_.backoff_max);
    return {0, Event::OpenFailed};
  }
  pollfd p{fd_, POLLIN, 0};
  const int ready = ::poll(&p, 1, static_cast<int>(timeout.count()));
  if (ready < 0) {
    if (errno == EINTR) return {};
    fail("poll failed: " + errno_text(errno), true);
  } else if (ready == 0) {
    return {};
  } else {
    // Read even on POLLHUP: bytes sent before the hang-up are still there.
    const ssize_t n = ::read(fd_, buffer, capacity);
    if (n > 0) {
      c_.bytes_read += static_cast<std::uint64_t>(n);
      return {static_cast<std::size_t>(n), Event::Data};
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      if (!(p.revents & (POLLHUP | POLLERR | POLLNVAL))) return {};
      fail("device hung up", true);
    } else if (n == 0) {
      fail("end of file (device gone)", true);
    } else {
      fail("read failed: " + errno_text(errno), true);
    }
  }
  close();
  next_attempt_ = clock::now() + backoff_;
  backoff_ = std::min(backoff_ * 2, options_.backoff_max);
  return {0, Event::Closed};
}

}  // namespace plumb::bridge
