// The benchmark's result tables (Markdown, so that they can be pasted into docs/benchmarks.md).
// Every plumb row is compared with the native programs of the same writer -> reader vendor pair
// measured in the same run, and with ddsperf (one octet array of the same size).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace plumb::bench {

enum class RowKind { Ddsperf, Native, Plumb };

struct LatencyRow {
  std::string message;  // "SensorBatch (32 samples)"
  std::size_t payload_bytes = 0;
  RowKind kind = RowKind::Plumb;
  std::string pair;     // "cyclonedds -> fastdds" (ping side -> pong side), "native ...", "ddsperf"
  std::optional<double> median_us, p99_us;
  std::optional<double> native_median_us;   // the native programs of the same pair
  std::optional<double> ddsperf_median_us;  // ddsperf, same payload size
  // CPU time per round trip of the ping and pong processes together (every thread of both):
  // robust to a busy machine, unlike the wall-clock figures. None for ddsperf.
  std::optional<double> cpu_us, native_cpu_us;
};

struct ThroughputRow {
  std::string message;
  std::size_t payload_bytes = 0;
  RowKind kind = RowKind::Plumb;
  std::string pair;     // writer -> reader
  std::optional<double> messages_per_s;
  std::optional<double> loss_percent;
  std::optional<double> native_messages_per_s;
  std::optional<double> ddsperf_messages_per_s;
  // CPU time per message of the writer and reader processes together (source per message sent
  // plus sink per message received). None for ddsperf.
  std::optional<double> cpu_us, native_cpu_us;
};

void print_latency_table(std::ostream& out, const std::vector<LatencyRow>& rows);
void print_throughput_table(std::ostream& out, const std::vector<ThroughputRow>& rows);

}  // namespace plumb::bench
