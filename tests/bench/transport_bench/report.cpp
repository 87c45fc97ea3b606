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

std::optional<double> ratio(const std::optional<double>& value, const std::optional<double>& baseline) {
  if (!value || !baseline || *baseline <= 0) return std::nullopt;
  return *value / *baseline;
}

}  // namespace

void print_latency_table(std::ostream& out, const std::vector<LatencyRow>& rows) {
  out << "| message | payload (B) | ping -> pong | median one-way (us) | p99 one-way (us) | median / ddsperf median |\n"
      << "|---|---:|---|---:|---:|---:|\n";
  for (const auto& row : rows) {
    out << "| " << row.message << " | " << row.payload_bytes << " | " << row.pair << " | "
        << format(row.median_us, "%.1f") << " | " << format(row.p99_us, "%.1f") << " | "
        << (row.pair == "ddsperf" ? std::string("1 (baseline)") : format(ratio(row.median_us, row.baseline_median_us), "%.2f"))
        << " |\n";
  }
}

void print_throughput_table(std::ostream& out, const std::vector<ThroughputRow>& rows) {
  out << "| message | payload (B) | writer -> reader | messages/s | MB/s | lost (%) | messages/s / ddsperf |\n"
      << "|---|---:|---|---:|---:|---:|---:|\n";
  for (const auto& row : rows) {
    std::optional<double> megabytes;
    if (row.messages_per_s) megabytes = *row.messages_per_s * static_cast<double>(row.payload_bytes) / 1e6;
    out << "| " << row.message << " | " << row.payload_bytes << " | " << row.pair << " | "
        << format(row.messages_per_s, "%.0f") << " | " << format(megabytes, "%.1f") << " | "
        << (row.pair == "ddsperf" ? std::string("-") : format(row.loss_percent, "%.1f")) << " | "
        << (row.pair == "ddsperf" ? std::string("1 (baseline)")
                                  : format(ratio(row.messages_per_s, row.baseline_messages_per_s), "%.2f"))
        << " |\n";
  }
}

}  // namespace plumb::bench
