// The four roles of a measurement, as in plumb-bench-transport (tests/bench/transport_bench/roles.hpp):
//   ping   -> pong   latency: ping writes, pong echoes from its listener, ping times the round trip
//   source -> sink   throughput: source writes as fast as it can, sink counts what arrives
// Same topics, same QoS as plumb's roles; each prints one line "RESULT key=value ..." in the same
// format and returns 0, or explains on stderr and returns 1.
#pragma once

#include <string>

namespace native_fastdds {

int run_role(const std::string& role, const std::string& type, int domain_id, double seconds);

}  // namespace native_fastdds
