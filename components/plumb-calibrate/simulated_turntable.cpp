#include "simulated_turntable.hpp"

#include <chrono>

#include "offline.hpp"
#include "plumb/components/convert.hpp"
#include "plumb/transport/topic_names.hpp"

namespace plumb::calibrate_component {

SimulatedTurntable::SimulatedTurntable(const Options& o, std::vector<sim::StationPlan> plans,
                                       const std::atomic<int>& requested, const std::atomic<int>& refused)
    : options_(o), plans_(std::move(plans)), requested_(requested), refused_(refused),
      connection_(components::connect(o.transport, "plumb-calibrate-turntable")) {
  thread_ = std::thread([this] { run(); });
}

SimulatedTurntable::~SimulatedTurntable() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void SimulatedTurntable::run() {
  auto writer = transport::make_writer<topics::SensorBatch>(*connection_.participant, transport::topic_names::kSensorRaw,
                                                            transport::Qos::sensor_stream());
  const auto pkg = simulated_package(options_);
  sim::Rig rig;
  rig.seed = options_.sim_seed;
  rig.g = options_.g;
  rig.total_b = options_.total_field_ut;
  sim::TurntableStream stream(pkg, rig);
  int current = -1, corrections = 0;
  const auto wall_start = std::chrono::steady_clock::now();
  while (!stop_ && !components::g_stop) {
    const int want = requested_.load();
    const int refusals = refused_.load();
    if ((want != current || refusals != corrections) && want >= 0 && want < static_cast<int>(plans_.size())) {
      auto plan = plans_[static_cast<std::size_t>(want)];
      if (want + 1 == options_.sim_misplace && current != want) {
        // A new operator's usual mistake: z pointing down whatever was asked (upside down if z
        // down was asked).
        plan.inclination_deg = plan.inclination_deg < 1 ? 180 : 0;
        plan.toolface_deg = 0;
      }
      stream.move_to(plan);
      current = want;
      corrections = refusals;
    }
    topics::SensorBatch batch;
    batch.tool_id = "sim-turntable";
    for (int i = 0; i < 32; ++i) batch.samples.push_back(components::to_topic(stream.next()));
    writer.write(batch);
    const auto due = wall_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(stream.time() / options_.sim_speed));
    std::this_thread::sleep_until(due);
  }
}

}  // namespace plumb::calibrate_component
