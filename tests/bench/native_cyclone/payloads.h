/* The benchmark's two messages in idlc's C types, filled like plumb-bench-transport's payloads
 * (tests/bench/transport_bench/payloads.cpp) so that the bytes on the wire are the same. */
#ifndef PLUMB_BENCH_NATIVE_CYCLONE_PAYLOADS_H
#define PLUMB_BENCH_NATIVE_CYCLONE_PAYLOADS_H

#include <dds/dds.h>
#include <stdint.h>

/* A sequence number that tells the receiver to stop (the same as plumb's kStopSeq). */
#define STOP_SEQ UINT64_MAX

/* What the roles need to know about a message type. */
typedef struct message_kind {
  const dds_topic_descriptor_t* descriptor;
  void* (*make)(void);             /* a filled sample; free with release() */
  void (*release)(void* sample);
  void (*set_seq)(void* sample, uint64_t seq);
  uint64_t (*get_seq)(const void* sample);
} message_kind;

/* "sensor" (SensorBatch, 32 samples) or "attitude"; NULL for another name. */
const message_kind* find_message_kind(const char* name);

#endif
