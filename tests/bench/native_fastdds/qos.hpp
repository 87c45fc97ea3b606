// The participant and endpoint QoS of plumb's Fast DDS plugin (transports/fastdds/src/qos.cpp),
// written out here for the loopback case only: the baseline shares no code with plumb, but it must
// run with the same settings so that the comparison measures plumb's code, not a configuration.
#pragma once

#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>

#include <cstdint>

namespace native_fastdds {

// plumb's Qos::attitude() history (latency) and Qos::reliable_stream() history (throughput).
inline constexpr std::int32_t kLatencyDepth = 64;
inline constexpr std::int32_t kThroughputDepth = 4096;

eprosima::fastdds::dds::DomainParticipantQos loopback_participant_qos(const char* name);
eprosima::fastdds::dds::DataWriterQos writer_qos(std::int32_t depth);
eprosima::fastdds::dds::DataReaderQos reader_qos(std::int32_t depth);

}  // namespace native_fastdds
