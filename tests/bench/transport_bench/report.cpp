#include "report.hpp"

#include <cstdio>

namespace plumb::bench {
namespace {

std::string format(const std::optional<double>& value, const char* pattern) {
  if (!value) return "failed";
  char text[64];
  std::snprintf(text, sizeof text, pattern, *value);
  return text;
}

std::string ratio(const std::optional<double>& value, const std::optional<double>& baseline) {
  if (!value || !baseline || *baseline <= 0) return "-";
  return format(*value / *baseline, "%.2f");
}

// Plumb rows compare with the native pair; native rows are that baseline; ddsperf has no native.
std::string native_ratio(RowKind kind, const std::optional<double>& value, const std::optional<double>& native) {
  if (kind == RowKind::Native) return "1 (baseline)";
  if (kind == RowKind::Ddsperf) return "-";
  return ratio(value, native);
}

std::string cpu(RowKind kind, const std::optional<double>& value) {
  return kind == RowKind::Ddsperf ? "-" : format(value, "%.1f");
}

std::string ddsperf_ratio(RowKind kind, const std::optional<double>& value, const std::optional<double>& ddsperf) {
  return kind == RowKind::Ddsperf ? "1" : ratio(value, ddsperf);
}

}  // namespace

void print_latency_table(std::ostream& out, const std::vector<LatencyRow>& rows) {
  out << "| message | payload (B) | ping -> pong | median one-way (us) | p99 one-way (us) | median / native | median / ddsperf "
         "| CPU per round trip (us) | CPU / native |\n"
      << "|---|---:|---|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& row : rows) {
    out << "| " << row.message << " | " << row.payload_bytes << " | " << row.pair << " | "
        << format(row.median_us, "%.1f") << " | " << format(row.p99_us, "%.1f") << " | "
        << native_ratio(row.kind, row.median_us, row.native_median_us) << " | "
        << ddsperf_ratio(row.kind, row.median_us, row.ddsperf_median_us) << " | " << cpu(row.kind, row.cpu_us) << " | "
        << native_ratio(row.kind, row.cpu_us, row.native_cpu_us) << " |\n";
  }
}

void print_throughput_table(std::ostream& out, const std::vector<ThroughputRow>& rows) {
  out << "| message | payload (B) | writer -> reader | messages/s | MB/s | lost (%) | messages/s / native | messages/s / ddsperf "
         "| CPU per message (us) | CPU / native |\n"
      << "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& row : rows) {
    std::optional<double> megabytes;
    if (row.messages_per_s) megabytes = *row.messages_per_s * static_cast<double>(row.payload_bytes) / 1e6;
    out << "| " << row.message << " | " << row.payload_bytes << " | " << row.pair << " | "
        << format(row.messages_per_s, "%.0f") << " | " << format(megabytes, "%.1f") << " | "
        << (row.kind == RowKind::Ddsperf ? std::string("-") : format(row.loss_percent, "%.1f")) << " | "
        << native_ratio(row.kind, row.messages_per_s, row.native_messages_per_s) << " | "
        << ddsperf_ratio(row.kind, row.messages_per_s, row.ddsperf_messages_per_s) << " | " << cpu(row.kind, row.cpu_us)
        << " | " << native_ratio(row.kind, row.cpu_us, row.native_cpu_us) << " |\n";
  }
}

}  // namespace plumb::bench
