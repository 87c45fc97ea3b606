// The messages the benchmark sends: full-size sensor batches (32 samples) and attitude messages,
// each carrying a sequence number, and their serialized (XCDR1) size so that ddsperf can be run with
// the same payload size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "plumb/transport/transport.hpp"

namespace plumb::bench {

// A sequence number that tells the receiver to stop.
inline constexpr std::uint64_t kStopSeq = UINT64_MAX;

template <class T> T make_payload();
template <> topics::SensorBatch make_payload<topics::SensorBatch>();
template <> topics::Attitude make_payload<topics::Attitude>();

void set_seq(topics::SensorBatch& batch, std::uint64_t seq);
void set_seq(topics::Attitude& attitude, std::uint64_t seq);
std::uint64_t get_seq(const topics::SensorBatch& batch);
std::uint64_t get_seq(const topics::Attitude& attitude);

// Bytes of the serialized sample after the 4-byte encapsulation header, as both vendors send it.
std::size_t serialized_size(const topics::SensorBatch& batch);
std::size_t serialized_size(const topics::Attitude& attitude);

}  // namespace plumb::bench
