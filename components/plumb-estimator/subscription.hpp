// The host's input: sensor batches from one topic, turned into samples per tool id (tool_streams.hpp:
// each tool is its own stream with its own sequence accounting), with every sequence gap, unselected
// tool and uncalibrated sample counted (the stream is best-effort by default), and the rig's
// measured depth (plumb/depth) attached to the samples of its tool that follow it.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "plumb/components/status_reporter.hpp"
#include "plumb/core/sample.hpp"
#include "plumb/transport/transport.hpp"
#include "resume_record.hpp"
#include "tool_streams.hpp"

namespace plumb::estimator_component {

struct SubscriptionOptions {
  std::string topic;
  std::string tool_id;  // "": every tool is its own stream; else only this tool, the others counted
  bool reliable = false;
};

class SensorSubscription {
 public:
  SensorSubscription(transport::Participant& participant, const SubscriptionOptions& options);
  using ToolChunks = std::map<std::string, std::vector<Sample>>;  // tool id -> its samples
  // Appends every sample that arrived to its tool's chunk in `out`; false when nothing came.
  bool take(ToolChunks& out);
  bool wait(std::chrono::nanoseconds timeout) { return reader_.wait(timeout); }
  std::size_t matched_writers() const { return reader_.matched_writers(); }
  // After a pause: the next sequence number is not expected to follow the last one.
  void restart_sequence() { streams_.restart_all(); }
  components::CounterList counters() const;
  std::uint64_t samples() const { return samples_; }
  std::uint64_t lost_samples() const { return streams_.lost(); }
  std::uint64_t silent_lost_samples() const { return streams_.silent_lost(); }
  std::size_t tools() const { return streams_.streams().size(); }
  std::uint64_t batches() const { return batches_; }
  // The previous instance's marks (resume_record.hpp): each tool's first batch is compared with
  // its mark, and the samples sent while this host was down are counted (lost_while_down).
  void resume_after(const ToolMarks& previous);
  // Where each tool stands now (with the previous instance's marks of tools not seen yet).
  const ToolMarks& marks() const { return marks_; }
  std::uint64_t lost_while_down() const { return lost_while_down_; }

 private:
  void take_depth();
  void note_stream_change(const std::string& tool, const SequenceAccount& account, std::uint64_t seq);
  // One batch into its tool's chunk (the take loop stays a loop over batches).
  bool route(const topics::SensorBatch& batch, ToolChunks& out);
  void count_loss_while_down(const std::string& tool, const topics::SensorBatch& batch, std::int64_t wall_ns);
  transport::Reader<topics::SensorBatch> reader_;
  transport::Reader<topics::MeasuredDepth> depth_reader_;
  topics::MeasuredDepth depth_msg_;
  std::map<std::string, double> depth_m_;  // per tool id; "" holds for every tool
  std::uint64_t depth_messages_ = 0;
  SubscriptionOptions options_;
  ToolStreams streams_;
  bool expect_calibrated_;
  bool warned_other_tool_ = false, warned_uncalibrated_ = false;
  std::vector<topics::SensorBatch> taken_;  // reused by every take: its messages keep their capacity
  std::uint64_t batches_ = 0, samples_ = 0;
  std::uint64_t uncalibrated_samples_ = 0;
  ToolMarks previous_, marks_;
  std::uint64_t lost_while_down_ = 0;
};

}  // namespace plumb::estimator_component
