// The four processes of a measurement. The benchmark starts itself as child processes in these
// roles, so that every measurement crosses a process boundary over loopback as in real use:
//   ping   -> pong   latency: ping writes, pong echoes from its data callback, ping times the round trip
//   source -> sink   throughput: source writes as fast as it can, sink counts what arrives
// Each role prints one line "RESULT key=value ..." on stdout and exits 0, or explains on stderr.
#pragma once

#include <string>

namespace plumb::bench {

struct RoleOptions {
  std::string role;       // ping, pong, source or sink
  std::string transport;  // fastdds or cyclonedds
  std::string type;       // sensor or attitude
  int domain_id = 0;
  double seconds = 2;     // how long to measure
};

int run_role(const RoleOptions& options);

// Topic names of the benchmark (not plumb's well-known topics, so that nothing else listens).
inline constexpr const char* kPingTopic = "plumb/bench/ping";
inline constexpr const char* kPongTopic = "plumb/bench/pong";
inline constexpr const char* kDataTopic = "plumb/bench/data";

}  // namespace plumb::bench
