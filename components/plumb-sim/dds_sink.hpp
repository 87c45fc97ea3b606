// Publishes sensor batches and the truth (one per batch) on DDS through the vendor-neutral transport.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "plumb/components/cli.hpp"
#include "plumb/components/status_reporter.hpp"
#include "plumb/transport/transport.hpp"
#include "rig_feed.hpp"
#include "sink.hpp"

namespace plumb::sim_component {

struct DdsSinkOptions {
  components::TransportOptions transport;
  std::string sensor_topic;
  std::string truth_topic;        // empty: no truth
  bool reliable = false;
  double wait_subscribers_s = 5;  // bounded wait for a matched reader (and plumb-wits) before the first batch
  double linger_s = 1;            // after the last batch, for reliable readers to catch up
  std::string tool_id;
  // The depth's stamps on a rig clock: t + offset + drift t (t the sensors' time).
  double rig_clock_offset_s = 0;
  double rig_clock_drift = 0;
  // HOST:PORT: the depth goes to plumb-wits as the rig's WITS feed instead of plumb/depth, and the
  // rig clock is this computer's (plumb-wits stamps on arrival): the sensors are then stamped on a
  // tool clock that is offset behind it and drift slow, from this computer's clock at the start.
  std::string wits_to;
  double wits_interval_s = 1;
};

class DdsSink final : public Sink {
 public:
  // Throws transport::Error when the transport cannot start.
  explicit DdsSink(const DdsSinkOptions& options);
  std::string describe() const override;
  bool start() override;
  void write(const std::vector<Sample>& samples, const std::vector<TruthSample>& truth) override;
  void finish(bool interrupted) override;
  std::uint64_t messages() const override { return batches_; }
  bool carries_depth() const override { return true; }

 private:
  DdsSinkOptions options_;
  components::Connection connection_;
  std::optional<transport::Writer<topics::SensorBatch>> sensor_;
  std::optional<transport::Writer<topics::Truth>> truth_;
  std::optional<transport::Writer<topics::MeasuredDepth>> depth_;  // created with the first depth
  std::optional<components::StatusReporter> status_;
  std::optional<RigFeed> rig_;
  std::int64_t tool_clock_origin_ns_ = 0;  // with rig_: the tool clock's reading at run time 0
  std::uint64_t batches_ = 0, samples_ = 0, depth_messages_ = 0;

  std::int64_t tool_stamp_ns(double t_s) const;
  void start_tool_clock(double t_s);
  components::CounterList counters() const;
};

}  // namespace plumb::sim_component
