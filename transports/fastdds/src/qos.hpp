// Translation of plumb's QoS profiles and participant options into Fast DDS QoS, following the
// interoperability rules of docs/architecture.md (XCDR1, UDPv4 only, loopback-only by default).
#pragma once

#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::fastdds {

// Throws Error for a domain id outside 0..232 or an interface this host does not have.
eprosima::fastdds::dds::DomainParticipantQos participant_qos(const ParticipantOptions& options);
eprosima::fastdds::dds::DataWriterQos writer_qos(const Qos& qos);
eprosima::fastdds::dds::DataReaderQos reader_qos(const Qos& qos);

}  // namespace plumb::transport::fastdds
