#include "qos.hpp"

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include <algorithm>
#include <memory>
#include <string>

#include "network_interface.hpp"
#include "plumb/transport/discovery_timing.hpp"
#include "plumb/transport/security.hpp"

namespace plumb::transport::fastdds {
namespace {

namespace dds = eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;

constexpr int kMaxDomainId = 232;  // the highest id whose RTPS ports stay below 65536
// Unicast-only discovery on loopback reaches participant indices 0..N-1 on this host. Both vendors
// derive a participant's discovery port from its index (7410 + 250 d + 2 i), so this also reaches
// the Cyclone DDS plugin's participants: 0..40 is its MaxAutoParticipantIndex range.
constexpr std::uint32_t kLoopbackPeerRange = 41;

constexpr std::uint32_t kSocketBufferBytes = 4u << 20;
constexpr std::int32_t kShortHistory = 64;

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
  reliability.kind = in.reliability == Reliability::Reliable ? dds::RELIABLE_RELIABILITY_QOS : dds::BEST_EFFORT_RELIABILITY_QOS;
  durability.kind = in.durability == Durability::TransientLocal ? dds::TRANSIENT_LOCAL_DURABILITY_QOS : dds::VOLATILE_DURABILITY_QOS;
  if (in.history == History::KeepAll) {
    history.kind = dds::KEEP_ALL_HISTORY_QOS;
    limits.max_samples = 5000;
    limits.max_samples_per_instance = 5000;
  } else {
    if (in.depth < 1) throw Error("QoS history depth must be at least 1, got " + std::to_string(in.depth));
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

// Fast DDS's builtin plugins (PKI-DH, Access-Permissions, AES-GCM-GMAC) on the checked files.
// Fast DDS 2.9 reads only file:// URIs ("file:" alone is taken as a missing file).
void add_security(dds::DomainParticipantQos& qos, const SecurityFiles& files) {
  auto& properties = qos.properties().properties();
  auto set = [&](const std::string& name, const std::string& value) { properties.emplace_back(name, value); };
  const std::string uri = "file://";
  set("dds.sec.auth.plugin", "builtin.PKI-DH");
  set("dds.sec.auth.builtin.PKI-DH.identity_ca", uri + files.identity_ca);
  set("dds.sec.auth.builtin.PKI-DH.identity_certificate", uri + files.certificate);
  set("dds.sec.auth.builtin.PKI-DH.private_key", uri + files.private_key);
  set("dds.sec.access.plugin", "builtin.Access-Permissions");
  set("dds.sec.access.builtin.Access-Permissions.permissions_ca", uri + files.permissions_ca);
  set("dds.sec.access.builtin.Access-Permissions.governance", uri + files.governance);
  set("dds.sec.access.builtin.Access-Permissions.permissions", uri + files.permissions);
  set("dds.sec.crypto.plugin", "builtin.AES-GCM-GMAC");
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
  // The system default (about 200 kB) holds some 60 sensor batches; bigger buffers absorb bursts.
  // The kernel caps these at net.core.rmem_max / wmem_max.
  udp->receiveBufferSize = kSocketBufferBytes;
  udp->sendBufferSize = kSocketBufferBytes;
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
  if (!options.security.empty()) add_security(qos, check_security_files(options.security));
  // The same participant lease and announcement period as the Cyclone DDS plugin
  // (plumb/transport/discovery_timing.hpp; transports/cyclonedds/domain_config.cpp says why).
  const DiscoveryTiming timing = discovery_timing();
  auto& discovery = qos.wire_protocol().builtin.discovery_config;
  discovery.leaseDuration = eprosima::fastrtps::Duration_t(static_cast<long double>(timing.lease_s));
  discovery.leaseDuration_announcementperiod = eprosima::fastrtps::Duration_t(static_cast<long double>(timing.announce_s));
  return qos;
}

dds::DataWriterQos writer_qos(const Qos& in) {
  dds::DataWriterQos qos = dds::DATAWRITER_QOS_DEFAULT;
  apply(in, qos.reliability(), qos.durability(), qos.history(), qos.resource_limits(), qos.representation());
  // Repair lost samples as quickly as Cyclone DDS does (its heartbeat is 100 ms; Fast DDS's 3 s).
  qos.reliable_writer_qos().times.heartbeatPeriod = eprosima::fastrtps::Duration_t(0, 100000000u);
  // A heartbeat with every sample makes the reader acknowledge every sample: twice the packets and
  // more wake-ups, about a quarter of the latency on loopback. Short keep-last histories (the
  // attitude, status and calibration profiles) never wait for acknowledgements, so the periodic
  // heartbeat suffices. Deep or keep-all histories keep it: without prompt acknowledgements the
  // writer's bookkeeping of thousands of unacknowledged samples halved the throughput.
  qos.reliable_writer_qos().disable_heartbeat_piggyback = in.history == History::KeepLast && in.depth <= kShortHistory;
  // With the default suppression of 0, every sample sent starts a timer that fires at once: one
  // wake-up of the event thread per message, which doubled the latency on a busy 2-core machine.
  // 5 ms: a NACK for a sample sent less than 5 ms ago is answered by the next heartbeat instead.
  qos.reliable_writer_qos().times.nackSupressionDuration = eprosima::fastrtps::Duration_t(0, 5000000u);
  // No shared-memory data sharing: UDP only (docs/architecture.md).
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
