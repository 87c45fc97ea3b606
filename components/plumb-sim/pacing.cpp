#include "pacing.hpp"

#include <cmath>
#include <stdexcept>
#include <thread>

#include "plumb/components/cli.hpp"

namespace plumb::sim_component {

double parse_speed(const std::string& text) {
  if (text == "realtime") return 1.0;
  if (text == "max") return 0.0;
  std::string number = text;
  if (!number.empty() && (number.front() == 'x' || number.front() == 'X')) number.erase(0, 1);
  else if (!number.empty() && (number.back() == 'x' || number.back() == 'X')) number.pop_back();
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(number, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != number.size() || !std::isfinite(v) || v <= 0)
    throw std::invalid_argument("--rate: expected realtime, xN (N > 0 times faster) or max, got '" + text + "'");
  return v;
}

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
