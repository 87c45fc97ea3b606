#include "dds_sink.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <thread>

#include "plumb/components/convert.hpp"

namespace plumb::sim_component {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

DdsSink::DdsSink(const DdsSinkOptions& options) : options_(options) {
  connection_ = components::connect(options_.transport, "plumb-sim");
  const auto qos = options_.reliable ? transport::Qos::reliable_stream() : transport::Qos::sensor_stream();
  sensor_.emplace(transport::make_writer<topics::SensorBatch>(*connection_.participant, options_.sensor_topic, qos));
  if (!options_.truth_topic.empty())
    // Reliable runs keep every truth message too, even at --rate max (a deep history).
    truth_.emplace(transport::make_writer<topics::Truth>(
        *connection_.participant, options_.truth_topic,
        options_.reliable ? transport::Qos::reliable_stream() : transport::Qos::attitude()));
  // Drilling runs carry the rig's measured depth: its writer exists from the start, so that readers
  // have matched before the first report.
  if (!options_.wits_to.empty())
    rig_.emplace(options_.wits_to, options_.wits_interval_s);
  else
    depth_.emplace(transport::make_writer<topics::MeasuredDepth>(
        *connection_.participant, transport::topic_names::kDepth,
        transport::default_qos_for_topic(transport::topic_names::kDepth)));
  status_.emplace(*connection_.participant, "plumb-sim");
}

std::string DdsSink::describe() const {
  std::ostringstream out;
  out << connection_.transport->name() << " topic " << options_.sensor_topic << " ("
      << (options_.reliable ? "reliable" : "best effort") << ")";
  if (truth_) out << ", truth on " << options_.truth_topic;
  if (rig_)
    out << ", " << rig_->describe() << " on this computer's clock, the tool's " << options_.rig_clock_offset_s
        << " s behind it and " << options_.rig_clock_drift * 1e6 << " ppm slow";
  else if (options_.rig_clock_offset_s != 0 || options_.rig_clock_drift != 0)
    out << ", depth on a rig clock " << options_.rig_clock_offset_s << " s ahead, " << options_.rig_clock_drift * 1e6
        << " ppm fast";
  return out.str();
}

bool DdsSink::start() {
  // plumb-wits may be starting beside the simulator (a launch file): the rig's feed waits for it,
  // and says whether it came (RigFeed::connect).
  if (rig_) rig_->connect(options_.wait_subscribers_s);
  if (options_.wait_subscribers_s <= 0) return true;
  // Discovery takes a moment: without this wait the first batches go to nobody.
  const auto until = Clock::now() + std::chrono::duration<double>(options_.wait_subscribers_s);
  while (sensor_->matched_readers() == 0 && Clock::now() < until && !components::g_stop)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  if (components::g_stop) return false;
  if (sensor_->matched_readers() == 0)
    std::cout << "plumb-sim: no reader on " << options_.sensor_topic << " after " << options_.wait_subscribers_s
              << " s; publishing anyway" << std::endl;
  else
    std::cout << "plumb-sim: " << sensor_->matched_readers() << " reader(s) matched on " << options_.sensor_topic
              << std::endl;
  return true;
}

// The tool's clock is this computer's at run time 0 (the first batch leaves when its last sample
// was measured), less the offset, running slow by the drift: so this computer's clock, which
// plumb-wits stamps the rig's frames with, is the offset ahead and the drift fast.
void DdsSink::start_tool_clock(double t_s) {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  tool_clock_origin_ns_ = std::chrono::duration_cast<std::chrono::nanoseconds>(now).count() - components::seconds_to_ns(t_s);
  std::cout << std::fixed << std::setprecision(3) << "plumb-sim: the tool's clock reads "
            << static_cast<double>(tool_clock_origin_ns_) * 1e-9 - options_.rig_clock_offset_s
            << " s at run time 0 (this computer's clock then " << static_cast<double>(tool_clock_origin_ns_) * 1e-9
            << " s, less " << options_.rig_clock_offset_s << " s) and runs " << options_.rig_clock_drift * 1e6
            << " ppm slow" << std::defaultfloat << std::endl;
}

std::int64_t DdsSink::tool_stamp_ns(double t_s) const {
  if (!rig_) return components::seconds_to_ns(t_s);
  return tool_clock_origin_ns_ + components::seconds_to_ns(t_s * (1 - options_.rig_clock_drift) - options_.rig_clock_offset_s);
}

components::CounterList DdsSink::counters() const {
  components::CounterList c{{"batches", batches_}, {"samples", samples_}, {"depth_messages", depth_messages_}};
  if (rig_) c.insert(c.end(), {{"wits_frames", rig_->frames_sent()}, {"wits_frames_lost", rig_->frames_lost()}});
  return c;
}

void DdsSink::write(const std::vector<Sample>& samples, const std::vector<TruthSample>& truth) {
  if (rig_ && batches_ == 0 && !samples.empty()) start_tool_clock(samples.back().t);
  if (rig_ && !samples.empty() && (samples.back().flags & flags::kHasDepth) != 0)
    rig_->at(samples.back().t, samples.back().depth_m);
  // The depth goes first, so that a reader holds it when the batch it belongs to arrives.
  if (depth_ && !samples.empty() && (samples.back().flags & flags::kHasDepth) != 0) {
    auto depth = components::to_depth(samples.back(), options_.tool_id);
    const double t = samples.back().t;
    depth.stamp_ns = components::seconds_to_ns(t + options_.rig_clock_offset_s + options_.rig_clock_drift * t);
    depth_->write(depth);
    ++depth_messages_;
  }
  topics::SensorBatch batch;
  batch.tool_id = components::bounded(options_.tool_id, topics::Attitude::kToolIdMax);
  batch.samples.reserve(samples.size());
  for (const auto& s : samples) {
    batch.samples.push_back(components::to_topic(s));
    batch.samples.back().stamp_ns = tool_stamp_ns(s.t);
  }
  sensor_->write(batch);
  ++batches_;
  samples_ += samples.size();
  if (status_->due()) {
    components::CounterList c = counters();
    c.emplace_back("readers", sensor_->matched_readers());
    status_->publish("running", c);
  }
  if (truth_ && !truth.empty()) {
    topics::Truth t = components::to_topic(truth.back(), options_.tool_id);
    t.stamp_ns = tool_stamp_ns(truth.back().t);
    truth_->write(t);
  }
}

void DdsSink::finish(bool interrupted) {
  // Reliable delivery of the last batches needs the writer alive until readers acknowledge.
  status_->publish(interrupted ? "stopping" : "finished", counters());
  if (rig_)
    std::cout << "plumb-sim: " << rig_->frames_sent() << " WITS frames sent to " << options_.wits_to << ", "
              << rig_->frames_lost() << " lost" << std::endl;
  if (!interrupted && batches_ > 0) components::sleep_while_running(options_.linger_s);
}

}  // namespace plumb::sim_component
