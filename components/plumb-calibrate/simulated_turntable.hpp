// A simulated turntable with a simulated operator, publishing raw sensor batches on
// plumb/sensor/raw from its own participant: it puts the tool at whichever position the live
// procedure asks for next, so that the live path runs end to end without hardware. With
// --sim-misplace N the operator gets position N wrong once (z axis down instead), and puts it right
// when the procedure refuses it.
#pragma once

#include <atomic>
#include <thread>
#include <vector>

#include "options.hpp"
#include "plumb/sim/turntable.hpp"

namespace plumb::calibrate_component {

class SimulatedTurntable {
 public:
  SimulatedTurntable(const Options& o, std::vector<sim::StationPlan> plans, const std::atomic<int>& requested,
                     const std::atomic<int>& refused);
  ~SimulatedTurntable();
  SimulatedTurntable(const SimulatedTurntable&) = delete;
  SimulatedTurntable& operator=(const SimulatedTurntable&) = delete;

 private:
  void run();
  Options options_;
  std::vector<sim::StationPlan> plans_;
  const std::atomic<int>& requested_;
  const std::atomic<int>& refused_;
  std::atomic<bool> stop_{false};
  components::Connection connection_;
  std::thread thread_;
};

}  // namespace plumb::calibrate_component
