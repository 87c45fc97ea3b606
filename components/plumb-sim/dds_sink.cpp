#include "dds_sink.hpp"

#include <chrono>
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
  if (options_.rig_clock_offset_s != 0 || options_.rig_clock_drift != 0)
    out << ", depth on a rig clock " << options_.rig_clock_offset_s << " s ahead, " << options_.rig_clock_drift * 1e6
        << " ppm fast";
  return out.str();
}

bool DdsSink::start() {
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

void DdsSink::write(const std::vector<Sample>& samples, const std::vector<TruthSample>& truth) {
  // The depth goes first, so that a reader holds it when the batch it belongs to arrives.
  if (!samples.empty() && (samples.back().flags & flags::kHasDepth) != 0) {
    auto depth = components::to_depth(samples.back(), options_.tool_id);
    const double t = samples.back().t;
    depth.stamp_ns = components::seconds_to_ns(t + options_.rig_clock_offset_s + options_.rig_clock_drift * t);
    depth_->write(depth);
    ++depth_messages_;
  }
  topics::SensorBatch batch;
  batch.tool_id = components::bounded(options_.tool_id, topics::Attitude::kToolIdMax);
  batch.samples.reserve(samples.size());
  for (const auto& s : samples) batch.samples.push_back(components::to_topic(s));
  sensor_->write(batch);
  ++batches_;
  samples_ += samples.size();
  if (status_->due())
    status_->publish("running", {{"batches", batches_}, {"samples", samples_}, {"depth_messages", depth_messages_},
                                 {"readers", sensor_->matched_readers()}});
  if (truth_ && !truth.empty()) truth_->write(components::to_topic(truth.back(), options_.tool_id));
}

void DdsSink::finish(bool interrupted) {
  // Reliable delivery of the last batches needs the writer alive until readers acknowledge.
  status_->publish(interrupted ? "stopping" : "finished",
                   {{"batches", batches_}, {"samples", samples_}, {"depth_messages", depth_messages_}});
  if (!interrupted && batches_ > 0) components::sleep_while_running(options_.linger_s);
}

}  // namespace plumb::sim_component
