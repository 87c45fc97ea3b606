#include "qos.hpp"

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include <memory>
#include <string>

#include "network_interface.hpp"

namespace plumb::transport::fastdds {
namespace {

namespace dds = eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;

constexpr int kMaxDomainId = 232;  // the highest id whose RTPS ports stay below 65536
// Unicast-only discovery on loopback reaches participants 0..N-1 of each process on this host; both
// vendors derive a participant's discovery port from its index (7410 + 250 d + 2 i), so this also
// reaches Cyclone DDS participants that use a participant index.
constexpr std::uint32_t kLoopbackPeerRange = 41;  // indices 0..40, as the Cyclone DDS plugin's MaxAutoParticipantIndex

rtps::Locator_t udp_locator(const std::string& address) {
  rtps::Locator_t locator;
  locator.kind = LOCATOR_KIND_UDPv4;
  rtps::IPLocator::setIPv4(locator, address);
  locator.port = 0;  // 0: Fast DDS fills in the well-known port of this participant
  return locator;
}

void apply(const Qos& in, dds::ReliabilityQosPolicy& reliability, dds::DurabilityQosPolicy& durability,
           dds::HistoryQosPolicy& history, dds::ResourceLimitsQosPolicy& limits,
           dds::DataRepresentationQosPolicy& representation) {
  if (in.depth < 1) throw Error("QoS history depth must be at least 1, got " + std::to_string(in.depth));
  reliability.kind = in.reliability == Reliability::Reliable ? dds::RELIABLE_RELIABILITY_QOS : dds::BEST_EFFORT_RELIABILITY_QOS;
  durability.kind = in.durability == Durability::TransientLocal ? dds::TRANSIENT_LOCAL_DURABILITY_QOS : dds::VOLATILE_DURABILITY_QOS;
  if (in.history == History::KeepAll) {
    history.kind = dds::KEEP_ALL_HISTORY_QOS;
    limits.max_samples = 5000;
    limits.max_samples_per_instance = 5000;
  } else {
    history.kind = dds::KEEP_LAST_HISTORY_QOS;
    history.depth = in.depth;
    // Fast DDS refuses a depth above its default per-instance limit (400); all our types are keyless.
    limits.max_samples = in.depth;
    limits.max_samples_per_instance = in.depth;
  }
  limits.max_instances = 1;
  limits.allocated_samples = std::min(limits.max_samples, 64);
  representation.m_value.clear();
  representation.m_value.push_back(dds::XCDR_DATA_REPRESENTATION);  // XCDR1, what Cyclone DDS 0.10 speaks
}

}  // namespace

dds::DomainParticipantQos participant_qos(const ParticipantOptions& options) {
  if (options.domain_id < 0 || options.domain_id > kMaxDomainId) {
    throw Error("domain id " + std::to_string(options.domain_id) + " is outside 0.." + std::to_string(kMaxDomainId));
  }
  const std::string address = resolve_ipv4_interface(options.interface);

  dds::DomainParticipantQos qos = dds::PARTICIPANT_QOS_DEFAULT;
  qos.name(options.name);

  // UDPv4 only: the shared-memory transport fails silently across users and containers.
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  udp->interfaceWhiteList.push_back(address);
  qos.transport().use_builtin_transports = false;

  if (is_loopback_address(address)) {
    // The loopback interface has no multicast: discover by unicast to the well-known ports of
    // this host, and receive discovery and data on the loopback address only.
    udp->maxInitialPeersRange = kLoopbackPeerRange;
    auto& builtin = qos.wire_protocol().builtin;
    builtin.initialPeersList.push_back(udp_locator(address));
    builtin.metatrafficUnicastLocatorList.push_back(udp_locator(address));
    qos.wire_protocol().default_unicast_locator_list.push_back(udp_locator(address));
  }
  qos.transport().user_transports.push_back(udp);
  return qos;
}

dds::DataWriterQos writer_qos(const Qos& in) {
  dds::DataWriterQos qos = dds::DATAWRITER_QOS_DEFAULT;
  apply(in, qos.reliability(), qos.durability(), qos.history(), qos.resource_limits(), qos.representation());
  // Repair lost samples as quickly as Cyclone DDS does (its heartbeat is 100 ms; Fast DDS's 3 s).
  qos.reliable_writer_qos().times.heartbeatPeriod = eprosima::fastrtps::Duration_t(0, 100000000u);
  // A heartbeat with every sample makes the reader acknowledge every sample: twice the packets and
  // a wake-up of Fast DDS's event thread per message, which costs about a quarter of the latency on
  // loopback. Keep-last writers never wait for acknowledgements, so the periodic heartbeat suffices;
  // keep-all writers keep it so that their history drains promptly.
  qos.reliable_writer_qos().disable_heartbeat_piggyback = in.history == History::KeepLast;
  // No shared-memory data sharing: UDP only (ARCHITECTURE.md).
  qos.data_sharing().off();
  return qos;
}

dds::DataReaderQos reader_qos(const Qos& in) {
  dds::DataReaderQos qos = dds::DATAREADER_QOS_DEFAULT;
  apply(in, qos.reliability(), qos.durability(), qos.history(), qos.resource_limits(),
        qos.type_consistency().representation);
  qos.data_sharing().off();
  return qos;
}

}  // namespace plumb::transport::fastdds
