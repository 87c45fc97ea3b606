#include "qos.hpp"

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include <algorithm>
#include <memory>

namespace native_fastdds {
namespace {

namespace dds = eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;

rtps::Locator_t loopback_locator() {
  rtps::Locator_t locator;
  locator.kind = LOCATOR_KIND_UDPv4;
  rtps::IPLocator::setIPv4(locator, "127.0.0.1");
  locator.port = 0;
  return locator;
}

// Reliable, volatile, keep-last `depth`, one instance, XCDR1.
template <class Qos> void common(Qos& qos, std::int32_t depth, dds::DataRepresentationQosPolicy& representation) {
  qos.reliability().kind = dds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = dds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = dds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = depth;
  qos.resource_limits().max_samples = depth;
  qos.resource_limits().max_samples_per_instance = depth;
  qos.resource_limits().max_instances = 1;
  qos.resource_limits().allocated_samples = std::min(depth, 64);
  representation.m_value.clear();
  representation.m_value.push_back(dds::XCDR_DATA_REPRESENTATION);
  qos.data_sharing().off();
}

}  // namespace

dds::DomainParticipantQos loopback_participant_qos(const char* name) {
  dds::DomainParticipantQos qos = dds::PARTICIPANT_QOS_DEFAULT;
  qos.name(name);
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  udp->interfaceWhiteList.push_back("127.0.0.1");
  udp->receiveBufferSize = 4u << 20;
  udp->sendBufferSize = 4u << 20;
  udp->maxInitialPeersRange = 41;
  qos.transport().use_builtin_transports = false;
  qos.transport().user_transports.push_back(udp);
  auto& builtin = qos.wire_protocol().builtin;
  builtin.initialPeersList.push_back(loopback_locator());
  builtin.metatrafficUnicastLocatorList.push_back(loopback_locator());
  qos.wire_protocol().default_unicast_locator_list.push_back(loopback_locator());
  return qos;
}

dds::DataWriterQos writer_qos(std::int32_t depth) {
  dds::DataWriterQos qos = dds::DATAWRITER_QOS_DEFAULT;
  common(qos, depth, qos.representation());
  qos.reliable_writer_qos().times.heartbeatPeriod = eprosima::fastrtps::Duration_t(0, 100000000u);
  qos.reliable_writer_qos().disable_heartbeat_piggyback = depth <= 64;
  qos.reliable_writer_qos().times.nackSupressionDuration = eprosima::fastrtps::Duration_t(0, 5000000u);
  return qos;
}

dds::DataReaderQos reader_qos(std::int32_t depth) {
  dds::DataReaderQos qos = dds::DATAREADER_QOS_DEFAULT;
  common(qos, depth, qos.type_consistency().representation);
  return qos;
}

}  // namespace native_fastdds
