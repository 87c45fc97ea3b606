#include "rig_feed.hpp"

#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <ctime>
#include <iostream>
#include <thread>

#include "plumb/components/cli.hpp"
#include "plumb/wits/frame_writer.hpp"
#include "plumb/wits/link.hpp"

namespace plumb::sim_component {

RigFeed::RigFeed(const std::string& host_port, double interval_s) : interval_s_(interval_s) {
  wits::split_host_port(host_port, "--wits", host_, port_);
}

RigFeed::~RigFeed() {
  if (fd_ >= 0) ::close(fd_);
}

std::string RigFeed::describe() const {
  return "the rig's depth as WITS level 0 to " + host_ + ":" + std::to_string(port_);
}

bool RigFeed::try_connect() {
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (::getaddrinfo(host_.c_str(), std::to_string(port_).c_str(), &hints, &found) != 0) return false;
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  const bool ok = fd >= 0 && ::connect(fd, found->ai_addr, found->ai_addrlen) == 0;
  ::freeaddrinfo(found);
  if (!ok) {
    if (fd >= 0) ::close(fd);
    return false;
  }
  fd_ = fd;
  return true;
}

bool RigFeed::connect(double wait_s) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
  while (!try_connect()) {
    if (components::g_stop || std::chrono::steady_clock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  std::cout << "plumb-sim: the rig's WITS feed connected to " << host_ << ":" << port_ << std::endl;
  return true;
}

void RigFeed::at(double t_s, double depth_m) {
  if (t_s + 1e-9 < next_t_s_) return;
  next_t_s_ += interval_s_;
  if (fd_ < 0 && !try_connect()) {
    ++lost_;
    return;
  }
  // The bit on bottom while drilling; the hole depth follows it (the run drills ahead only).
  const std::string frame = wits::record01_frame(depth_m, depth_m, 1.0, std::time(nullptr));
  std::size_t done = 0;
  while (done < frame.size()) {
    const ssize_t n = ::send(fd_, frame.data() + done, frame.size() - done, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      std::cout << "plumb-sim: the rig's WITS feed lost its connection; opening it again at the next frame" << std::endl;
      ::close(fd_);
      fd_ = -1;
      ++lost_;
      return;
    }
    done += static_cast<std::size_t>(n);
  }
  ++sent_;
}

}  // namespace plumb::sim_component
