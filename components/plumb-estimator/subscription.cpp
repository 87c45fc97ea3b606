#include "subscription.hpp"

#include <chrono>
#include <iostream>

#include "plumb/components/convert.hpp"

namespace plumb::estimator_component {

SensorSubscription::SensorSubscription(transport::Participant& participant, const SubscriptionOptions& options)
    : reader_(transport::make_reader<topics::SensorBatch>(
          participant, options.topic,
          options.reliable ? transport::Qos::reliable_stream() : transport::Qos::sensor_stream())),
      depth_reader_(transport::make_reader<topics::MeasuredDepth>(
          participant, transport::topic_names::kDepth, transport::default_qos_for_topic(transport::topic_names::kDepth))),
      options_(options),
      streams_(options.tool_id),
      expect_calibrated_(options.topic == transport::topic_names::kSensorCalibrated) {}

// The latest depth of each tool; it holds for the samples taken after it (a rig reports about
// once a second, the sensors far faster).
void SensorSubscription::take_depth() {
  while (depth_reader_.take(depth_msg_)) {
    if ((depth_msg_.flags & topics::DEPTH_VALID) == 0) continue;
    if (!options_.tool_id.empty() && !depth_msg_.tool_id.empty() && depth_msg_.tool_id != options_.tool_id) continue;
    depth_m_[depth_msg_.tool_id] = depth_msg_.depth_m;
    ++depth_messages_;
  }
}

// Said in the log when it happens, so that an operator reading it knows where the host joined a
// stream and what a pause cost (the counters say how much in total).
void SensorSubscription::note_stream_change(const std::string& tool, const SequenceAccount& account, std::uint64_t seq) {
  const std::string who = "plumb-estimator: tool '" + tool + "'";
  if (!account.have_seq)
    std::cerr << who << " starts at sequence " << seq << (seq > 0 ? " (joined a running stream)" : "") << std::endl;
  else if (account.paused && seq > account.next_seq)
    std::cerr << who << " resumed after a silence at sequence " << seq << ": " << seq - account.next_seq
              << " samples lost while silent" << std::endl;
  else if (account.paused && seq < account.next_seq)
    std::cerr << who << " restarted its sequence (now " << seq << ", was " << account.next_seq - 1
              << "): a new source" << std::endl;
}

void SensorSubscription::resume_after(const ToolMarks& previous) {
  previous_ = previous;
  marks_ = previous;
}

// Said once per tool, at its first batch: how this instance's start relates to where the previous
// one stopped.
void SensorSubscription::count_loss_while_down(const std::string& tool, const topics::SensorBatch& batch,
                                               std::int64_t wall_ns) {
  const auto mark = previous_.find(tool);
  if (mark == previous_.end()) return;
  const std::uint64_t first = batch.samples.front().seq;
  const DownLoss d = loss_while_down(mark->second, first, batch.samples.back().stamp_ns, wall_ns);
  const std::string who = "plumb-estimator: tool '" + tool + "'";
  const std::string since =
      " (previous instance last seen at " + wall_time_text(mark->second.wall_ns) + ", sequence " +
      std::to_string(mark->second.last_seq) + ")";
  switch (d.kind) {
    case DownLoss::Kind::Lost:
      lost_while_down_ += d.count();
      if (d.count() > 0)
        std::cerr << "plumb-estimator: samples " << d.first << ".." << d.last << " of tool '" << tool
                  << "' were lost while this host was down: " << d.count() << " samples" << since << std::endl;
      else
        std::cerr << who << " resumes at sequence " << first << ", right after its previous instance" << since
                  << ": nothing lost while this host was down" << std::endl;
      break;
    case DownLoss::Kind::SourceRestarted:
      std::cerr << who << " restarted its sequence while this host was down (now " << first << ")" << since
                << ": a new source, nothing counted as lost while down" << std::endl;
      break;
    case DownLoss::Kind::ClocksDisagree:
      std::cerr << who << ": its clock moved " << d.stream_s << " s and this computer's " << d.wall_s
                << " s since the previous instance's record" << since
                << ": another run or a replay, nothing counted as lost while down" << std::endl;
      break;
  }
}

bool SensorSubscription::route(const topics::SensorBatch& batch, ToolChunks& out) {
  SequenceAccount* account = streams_.route(batch.tool_id);
  if (!account) {
    if (!warned_other_tool_) {
      std::cerr << "plumb-estimator: " << options_.topic << " also carries tool '" << batch.tool_id
                << "'; using only tool '" << options_.tool_id << "' (--tool-id), the others are counted" << std::endl;
      warned_other_tool_ = true;
    }
    return false;
  }
  if (streams_.streams().size() > 1 && !warned_other_tool_) {
    // Two tools on one topic: never one estimate from both; each gets its own.
    std::cerr << "plumb-estimator: " << options_.topic << " carries more than one tool (now also '" << batch.tool_id
              << "'): estimating each tool separately, attitude messages carry its tool id" << std::endl;
    warned_other_tool_ = true;
  }
  auto depth = depth_m_.find(batch.tool_id);
  if (depth == depth_m_.end()) depth = depth_m_.find("");
  auto& chunk = out[batch.tool_id];
  if (!batch.samples.empty()) {
    account->clock(components::ns_to_seconds(batch.samples.front().stamp_ns),
                   components::ns_to_seconds(batch.samples.back().stamp_ns));
    note_stream_change(batch.tool_id, *account, batch.samples.front().seq);
    const std::int64_t wall_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                     std::chrono::system_clock::now().time_since_epoch())
                                     .count();
    if (!account->have_seq) count_loss_while_down(batch.tool_id, batch, wall_ns);
    marks_[batch.tool_id] = {batch.samples.back().seq, batch.samples.back().stamp_ns, wall_ns};
  }
  for (const auto& m : batch.samples) {
    account->account(m.seq);
    chunk.push_back(components::from_topic(m));
    if (depth != depth_m_.end()) {
      chunk.back().depth_m = depth->second;
      chunk.back().flags |= flags::kHasDepth;
    }
    if (expect_calibrated_ && (chunk.back().flags & flags::kCalibrated) == 0) ++uncalibrated_samples_;
  }
  samples_ += batch.samples.size();
  return true;
}

bool SensorSubscription::take(ToolChunks& out) {
  bool any = false;
  take_depth();
  // Batched takes: one vendor call for everything that arrived since the last one (up to
  // kBatchesPerTake), not one call per message.
  constexpr std::size_t kBatchesPerTake = 64;
  while (reader_.take(taken_, kBatchesPerTake) > 0) {
    for (const auto& batch : taken_) {
      ++batches_;
      if (route(batch, out)) any = true;
    }
    if (taken_.size() < kBatchesPerTake) break;  // the reader is empty
  }
  if (uncalibrated_samples_ > 0 && !warned_uncalibrated_) {
    std::cerr << "plumb-estimator: samples on " << options_.topic
              << " are not calibrated (no calibration applied by the bridge); counted as uncalibrated_samples"
              << std::endl;
    warned_uncalibrated_ = true;
  }
  return any;
}

components::CounterList SensorSubscription::counters() const {
  return {{"batches", batches_},
          {"samples", samples_},
          {"tools", streams_.streams().size()},
          {"seq_gaps", streams_.gaps()},
          {"lost_samples", streams_.lost()},
          {"seq_backwards", streams_.backwards()},
          {"silent_gaps", streams_.silent_gaps()},
          {"silent_lost_samples", streams_.silent_lost()},
          {"lost_while_down", lost_while_down_},
          {"source_restarts", streams_.source_restarts()},
          {"other_tool_batches", streams_.other_tool_batches()},
          {"depth_messages", depth_messages_},
          {"uncalibrated_samples", uncalibrated_samples_}};
}

}  // namespace plumb::estimator_component
