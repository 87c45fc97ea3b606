/* The four roles of a measurement, as in plumb-bench-transport (tests/bench/transport_bench/roles.hpp):
 *   ping   -> pong   latency: ping writes, pong echoes from its listener, ping times the round trip
 *   source -> sink   throughput: source writes as fast as it can, sink counts what arrives
 * Same topics, same QoS as plumb's benchmark roles; each prints one line "RESULT key=value ..." in
 * the same format and returns 0, or explains on stderr and returns 1. */
#ifndef PLUMB_BENCH_NATIVE_CYCLONE_ROLES_H
#define PLUMB_BENCH_NATIVE_CYCLONE_ROLES_H

#include "payloads.h"

int run_ping(dds_entity_t participant, const message_kind* kind, double seconds);
int run_pong(dds_entity_t participant, const message_kind* kind, double seconds);
int run_source(dds_entity_t participant, const message_kind* kind, double seconds);
int run_sink(dds_entity_t participant, const message_kind* kind, double seconds);

#endif
