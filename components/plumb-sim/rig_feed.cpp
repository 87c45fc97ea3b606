#include "rig_feed.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <iostream>

#include "plumb/components/cli.hpp"
#include "plumb/wits/frame_writer.hpp"
#include "plumb/wits/link.hpp"

namespace plumb::sim_component {

RigFeed::RigFeed(const std::string& host_port, double interval_s) : interval_s_(interval_s) {
  std::string host;
  int port = 0;
  wits::split_host_port(host_port, "--wits", host, port);
  sender_.emplace(host, port);
}

std::string RigFeed::describe() const { return "the rig's depth as WITS level 0 to " + sender_->address(); }

bool RigFeed::connect(double wait_s) {
  std::cout << "plumb-sim: waiting for plumb-wits on " << sender_->address() << " (up to " << wait_s << " s)"
            << std::endl;
  const auto wait = std::chrono::milliseconds(std::llround(std::max(wait_s, 0.0) * 1000));
  if (!sender_->connect(wait, [] { return components::g_stop.load(); })) {
    if (!components::g_stop)
      std::cout << "plumb-sim: gave up waiting for plumb-wits: " << sender_->last_error()
                << "; the rig's frames are lost until it listens" << std::endl;
    return false;
  }
  std::cout << "plumb-sim: the rig's WITS feed connected to " << sender_->address() << std::endl;
  return true;
}

void RigFeed::at(double t_s, double depth_m) {
  if (t_s + 1e-9 < next_t_s_) return;
  next_t_s_ += interval_s_;
  // One attempt, its handshake bounded: the run goes on in real time whether plumb-wits is there or not.
  if (!sender_->is_open() && !sender_->connect(std::chrono::milliseconds(0))) {
    ++lost_;
    return;
  }
  // The bit on bottom while drilling; the hole depth follows it (the run drills ahead only).
  if (!sender_->send(wits::record01_frame(depth_m, depth_m, 1.0, std::time(nullptr)))) {
    std::cout << "plumb-sim: " << sender_->last_error() << "; opening it again at the next frame" << std::endl;
    ++lost_;
    return;
  }
  ++sent_;
}

}  // namespace plumb::sim_component
