// The simulated rig's depth as the rig itself gives it: a WITS level-0 feed (record 01 frames, one
// per interval of the run) over TCP to plumb-wits --listen, instead of plumb/depth. plumb-wits then
// stamps each frame with this computer's clock, as on a rig, so the depth and the sensors meet on two
// clocks (plumb-sim --wits; the rig-day launch file).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "plumb/wits/tcp_sender.hpp"

namespace plumb::sim_component {

class RigFeed {
 public:
  // HOST:PORT of plumb-wits --listen; throws std::invalid_argument on a bad address.
  RigFeed(const std::string& host_port, double interval_s);

  // Connects, trying for up to wait_s (plumb-wits may start after the simulator): one line when it
  // starts waiting, one when it connected or gave up (with the system's reason). False if nobody
  // listens by then (the frames are then lost until it does, and counted).
  bool connect(double wait_s);
  // The tool's measured depth at run time t: a frame once t reaches the next interval. A lost
  // connection is opened again at the next frame.
  void at(double t_s, double depth_m);

  std::uint64_t frames_sent() const { return sent_; }
  std::uint64_t frames_lost() const { return lost_; }
  std::string describe() const;

 private:
  std::optional<wits::TcpSender> sender_;
  double interval_s_;
  double next_t_s_ = 0;
  std::uint64_t sent_ = 0, lost_ = 0;
};

}  // namespace plumb::sim_component
