// The benchmark's two messages in fastddsgen's classes, filled like plumb-bench-transport's
// payloads (tests/bench/transport_bench/payloads.cpp) so that the bytes on the wire are the same.
#pragma once

#include <cstdint>

#include "plumb_idl/attitude.h"
#include "plumb_idl/attitudePubSubTypes.h"
#include "plumb_idl/sensor.h"
#include "plumb_idl/sensorPubSubTypes.h"

namespace native_fastdds {

// A sequence number that tells the receiver to stop (the same as plumb's kStopSeq).
inline constexpr std::uint64_t kStopSeq = UINT64_MAX;

void fill(plumb::msg::SensorBatch& batch);
void fill(plumb::msg::Attitude& attitude);

// The sequence number rides in the first sample's seq (batch) or in window_start_ns (attitude).
inline void set_seq(plumb::msg::SensorBatch& batch, std::uint64_t seq) { batch.samples()[0].seq(seq); }
inline void set_seq(plumb::msg::Attitude& attitude, std::uint64_t seq) {
  attitude.window_start_ns(static_cast<std::int64_t>(seq));
}
inline std::uint64_t get_seq(const plumb::msg::SensorBatch& batch) {
  return batch.samples().empty() ? 0 : batch.samples()[0].seq();
}
inline std::uint64_t get_seq(const plumb::msg::Attitude& attitude) {
  return static_cast<std::uint64_t>(attitude.window_start_ns());
}

}  // namespace native_fastdds
