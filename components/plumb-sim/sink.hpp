// Where plumb-sim's samples go. The main loop produces batches and paces them; a sink only
// delivers them. Sinks: DDS topics (dds_sink), CSV files (csv_sink); others (a serial port)
// are added as one more file implementing this interface.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "plumb/core/sample.hpp"

namespace plumb::sim_component {

class Sink {
 public:
  virtual ~Sink() = default;
  // Readable destination for the start-up log line: "DDS topic plumb/sensor/raw (best effort)".
  virtual std::string describe() const = 0;
  // Before the first batch; may wait (bounded) for consumers. Returns false if the run must stop.
  virtual bool start() { return true; }
  // One batch (at most topics::SensorBatch::kSamplesMax samples) and the truth of each sample.
  virtual void write(const std::vector<Sample>& samples, const std::vector<TruthSample>& truth) = 0;
  // After the last batch (also after Ctrl-C): flush, let reliable readers catch up.
  virtual void finish(bool interrupted) { (void)interrupted; }
  // Files are written as fast as possible; devices and topics follow the clock unless told otherwise.
  virtual bool paced() const { return true; }
  // How many messages carried the batches (DDS: one per batch; files: zero).
  virtual std::uint64_t messages() const { return 0; }
  // Whether write() delivers the measured depth of samples flagged flags::kHasDepth (drilling runs):
  // the CSV's depth_m column does; a sink that drops it keeps false, and plumb-sim says so at start.
  virtual bool carries_depth() const { return false; }
};

}  // namespace plumb::sim_component
