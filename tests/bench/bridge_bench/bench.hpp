// The two halves of plumb-bench-bridge.
#pragma once

#include <string>

namespace plumb::bench {

// Parser MB/s and frames/s beside memcpy and CRC-32 over the same bytes, same run.
void run_parser_throughput(std::size_t frames, int repeats);

struct CpuOptions {
  std::string bridge;     // path of plumb-bridge
  std::string transport;  // cyclonedds or fastdds
  int domain = 98;
  double seconds = 10;
  double rate_hz = 1000;
};
// CPU use of a real plumb-bridge process reading a pseudo-terminal fed at rate_hz, beside the
// same process idle (device open, no data). Returns false if the bridge could not run.
bool run_bridge_cpu(const CpuOptions& options);

}  // namespace plumb::bench
