#include "serial_sink.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <iostream>
#include <stdexcept>

#include "plumb/bridge/protocol.hpp"
#include "plumb/bridge/serial_port.hpp"

namespace plumb::sim_component {
namespace {

bool is_device(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

int open_device(const std::string& path, int baud) {
  const auto speed = bridge::baud_constant(baud);
  if (!speed) throw std::invalid_argument("--serial-baud " + std::to_string(baud) + " is not a standard rate");
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(path + ": cannot open: " + std::strerror(errno));
  termios tio{};
  if (::tcgetattr(fd, &tio) != 0) {
    ::close(fd);
    throw std::runtime_error(path + ": not a terminal device");
  }
  ::cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL;
  ::cfsetispeed(&tio, static_cast<speed_t>(*speed));
  ::cfsetospeed(&tio, static_cast<speed_t>(*speed));
  ::tcsetattr(fd, TCSANOW, &tio);
  return fd;
}

}  // namespace

SerialSink::SerialSink(const SerialSinkOptions& options) : options_(options) {
  if (options_.mode != "binary" && options_.mode != "ascii")
    throw std::invalid_argument("--serial-mode: expected binary or ascii, got '" + options_.mode + "'");
  if (is_device(options_.path)) {
    device_fd_ = open_device(options_.path, options_.baud);
    return;
  }
  pty_ = std::make_unique<bridge::PseudoTerminal>();
  bridge::replace_symlink(pty_->slave_path(), options_.path);
}

SerialSink::~SerialSink() {
  if (pty_) {
    bridge::remove_symlink(options_.path);
    pty_->close();
  }
  if (device_fd_ >= 0) ::close(device_fd_);
}

std::string SerialSink::describe() const {
  const std::string what = options_.mode == "binary" ? "binary frames" : "ASCII lines";
  if (pty_) return "serial pseudo-terminal " + options_.path + " -> " + pty_->slave_path() + " (" + what + ")";
  return "serial device " + options_.path + " at " + std::to_string(options_.baud) + " baud (" + what + ")";
}

bool SerialSink::write_bytes(const std::vector<std::uint8_t>& bytes) {
  // Once the line is full and nobody reads, do not wait again: a board keeps its clock, so the run
  // keeps its pace and --duration holds (the README runs `plumb-sim --serial ... --duration 60 &`).
  const auto timeout = reader_absent_ ? std::chrono::milliseconds(0)
                                      : std::chrono::milliseconds(static_cast<long long>(options_.write_timeout_s * 1000));
  if (pty_) return pty_->write_all(bytes.data(), bytes.size(), timeout);
  const std::uint8_t* p = bytes.data();
  std::size_t left = bytes.size();
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (left > 0) {
    const ssize_t n = ::write(device_fd_, p, left);
    if (n > 0) {
      p += n;
      left -= static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR) return false;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    pollfd pfd{device_fd_, POLLOUT, 0};
    ::poll(&pfd, 1, 100);
  }
  return true;
}

void SerialSink::write(const std::vector<Sample>& samples, const std::vector<TruthSample>&) {
  buffer_.clear();
  if (options_.mode == "binary") {
    for (const auto& s : samples) bridge::append_frame(buffer_, s);
  } else {
    std::string text;
    if (!header_sent_) text = bridge::ascii_header();
    header_sent_ = true;
    for (const auto& s : samples) text += bridge::encode_ascii_line(s);
    buffer_.assign(text.begin(), text.end());
  }
  if (write_bytes(buffer_)) {
    if (reader_absent_)
      std::cerr << "plumb-sim: serial " << options_.path << ": a reader is back; " << dropped_
                << " samples dropped so far" << std::endl;
    reader_absent_ = false;
    frames_ += samples.size();
    return;
  }
  // Nobody reads the line: like a real board, the samples are gone. Said when it starts, counted,
  // and the count is given at the end.
  if (!reader_absent_)
    std::cerr << "plumb-sim: serial " << options_.path << ": nobody reads the line; dropping samples until a reader "
              << "comes (start plumb-bridge --device " << options_.path << ")" << std::endl;
  reader_absent_ = true;
  dropped_ += samples.size();
}

void SerialSink::finish(bool interrupted) {
  // Let the bridge read what is still in the line before the device disappears.
  if (pty_ && !interrupted && !reader_absent_) pty_->drain(std::chrono::milliseconds(static_cast<long long>(options_.write_timeout_s * 1000)));
  if (device_fd_ >= 0 && !interrupted && !reader_absent_) ::tcdrain(device_fd_);
  std::cout << "plumb-sim: serial " << options_.path << ": " << frames_ << " samples written"
            << (dropped_ ? ", " + std::to_string(dropped_) + " dropped (no reader)" : std::string()) << std::endl;
}

}  // namespace plumb::sim_component
