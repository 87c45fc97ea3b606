#include "pacing.hpp"

#include <cmath>
#include <stdexcept>
#include <thread>

#include "plumb/components/cli.hpp"

namespace plumb::sim_component {

void Pacer::wait_until(double t) {
  if (speed_ <= 0) return;
  const auto now = std::chrono::steady_clock::now();
  if (!started_) {
    start_ = now;
    started_ = true;
  }
  const auto due = start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(t / speed_));
  // Short sleeps so that Ctrl-C is honoured even at slow rates.
  while (!components::g_stop) {
    const auto left = due - std::chrono::steady_clock::now();
    if (left <= std::chrono::steady_clock::duration::zero()) return;
    std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(left, std::chrono::milliseconds(50)));
  }
}

}  // namespace plumb::sim_component
