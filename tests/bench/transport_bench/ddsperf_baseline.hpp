// The baseline: Cyclone DDS's own ddsperf tool, run in the same loopback-only configuration as the
// plumb Cyclone plugin, with the same payload size, in the same run as plumb's measurements.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace plumb::bench {

struct DdsperfLatency {
  double median_us = 0;  // one-way (round trip / 2), as ddsperf reports it
  double p99_us = 0;
  std::size_t seconds_measured = 0;
};

struct DdsperfThroughput {
  double messages_per_s = 0;
};

// ddsperf ping/pong for `seconds`; nullopt (with a line on stderr) if ddsperf is missing or failed.
std::optional<DdsperfLatency> ddsperf_latency(const std::string& ddsperf, int domain_id, std::size_t payload_bytes,
                                              double seconds);
// ddsperf pub (as fast as possible) / sub.
std::optional<DdsperfThroughput> ddsperf_throughput(const std::string& ddsperf, int domain_id, std::size_t payload_bytes,
                                                    double seconds);

// CYCLONEDDS_URI contents matching the plumb Cyclone plugin's loopback setup.
std::string loopback_cyclone_config();

}  // namespace plumb::bench
