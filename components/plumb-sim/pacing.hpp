// Real-time pacing of the simulated stream: "realtime", "xN" (N times faster) or "max".
#pragma once

#include <chrono>
#include <string>

namespace plumb::sim_component {

class Pacer {
 public:
  explicit Pacer(double speed) : speed_(speed) {}
  // Sleeps until simulated time `t` (s since the start) is due; returns early on Ctrl-C.
  void wait_until(double t);

 private:
  double speed_;
  bool started_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace plumb::sim_component
