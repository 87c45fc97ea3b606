// The benchmark's result table (Markdown, so that it can be pasted into docs/benchmarks.md).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace plumb::bench {

struct LatencyRow {
  std::string message;  // "SensorBatch (32 samples)"
  std::size_t payload_bytes = 0;
  std::string pair;     // "cyclonedds -> fastdds" (ping side -> pong side) or "ddsperf"
  std::optional<double> median_us, p99_us;
  std::optional<double> baseline_median_us;  // ddsperf, same payload size
};

struct ThroughputRow {
  std::string message;
  std::size_t payload_bytes = 0;
  std::string pair;     // writer -> reader
  std::optional<double> messages_per_s;
  std::optional<double> loss_percent;
  std::optional<double> baseline_messages_per_s;
};

void print_latency_table(std::ostream& out, const std::vector<LatencyRow>& rows);
void print_throughput_table(std::ostream& out, const std::vector<ThroughputRow>& rows);

}  // namespace plumb::bench
