// Conversions between plumb::topics types and the C structs idlc generates from idl/*.idl.
#pragma once

#include <array>

#include "plumb/transport/messages.hpp"
#include "plumb_idl/attitude.h"
#include "plumb_idl/calibration.h"
#include "plumb_idl/sensor.h"
#include "plumb_idl/status.h"
#include "plumb_idl/truth.h"

namespace plumb::transport::cyclonedds {

// The generated C type and topic descriptor of each topics:: type.
template <class T> struct CType;
template <> struct CType<topics::SensorBatch> {
  using type = plumb_msg_SensorBatch;
  static const dds_topic_descriptor_t* descriptor() { return &plumb_msg_SensorBatch_desc; }
};
template <> struct CType<topics::Attitude> {
  using type = plumb_msg_Attitude;
  static const dds_topic_descriptor_t* descriptor() { return &plumb_msg_Attitude_desc; }
};
template <> struct CType<topics::CalibrationCoefficients> {
  using type = plumb_msg_CalibrationCoefficients;
  static const dds_topic_descriptor_t* descriptor() { return &plumb_msg_CalibrationCoefficients_desc; }
};
template <> struct CType<topics::ComponentStatus> {
  using type = plumb_msg_ComponentStatus;
  static const dds_topic_descriptor_t* descriptor() { return &plumb_msg_ComponentStatus_desc; }
};
template <> struct CType<topics::Truth> {
  using type = plumb_msg_Truth;
  static const dds_topic_descriptor_t* descriptor() { return &plumb_msg_Truth_desc; }
};

// Storage the C sequences of one outgoing message point into (no heap allocation per write).
struct OutgoingBuffers {
  std::array<plumb_msg_SensorSample, topics::kMaxSamplesPerBatch> samples;
  std::array<plumb_msg_Counter, topics::kMaxCountersPerStatus> counters;
};

// to_c throws Error when a string exceeds its IDL bound or a sequence its maximum length: the
// message would not be representable on the wire, and silently cutting it would lose data.
void to_c(const topics::SensorBatch& m, plumb_msg_SensorBatch& c, OutgoingBuffers& buffers);
void to_c(const topics::Attitude& m, plumb_msg_Attitude& c, OutgoingBuffers& buffers);
void to_c(const topics::CalibrationCoefficients& m, plumb_msg_CalibrationCoefficients& c, OutgoingBuffers& buffers);
void to_c(const topics::ComponentStatus& m, plumb_msg_ComponentStatus& c, OutgoingBuffers& buffers);
void to_c(const topics::Truth& m, plumb_msg_Truth& c, OutgoingBuffers& buffers);

void from_c(const plumb_msg_SensorBatch& c, topics::SensorBatch& m);
void from_c(const plumb_msg_Attitude& c, topics::Attitude& m);
void from_c(const plumb_msg_CalibrationCoefficients& c, topics::CalibrationCoefficients& m);
void from_c(const plumb_msg_ComponentStatus& c, topics::ComponentStatus& m);
void from_c(const plumb_msg_Truth& c, topics::Truth& m);

}  // namespace plumb::transport::cyclonedds
