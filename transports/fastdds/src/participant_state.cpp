#include "participant_state.hpp"

#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/rtps/builtin/data/ReaderProxyData.h>
#include <fastdds/rtps/builtin/data/WriterProxyData.h>

#include <chrono>
#include <thread>

#include "qos.hpp"
#include "type_support.hpp"

namespace plumb::transport::fastdds {

namespace dds = eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;

void DiscoveryMap::on_publisher_discovery(dds::DomainParticipant*, rtps::WriterDiscoveryInfo&& info) {
  if (info.status == rtps::WriterDiscoveryInfo::REMOVED_WRITER) {
    remove(info.info.guid());
  } else {
    add(info.info.guid(), info.info.topicName().to_string(), info.info.typeName().to_string(), true);
  }
}

void DiscoveryMap::on_subscriber_discovery(dds::DomainParticipant*, rtps::ReaderDiscoveryInfo&& info) {
  if (info.status == rtps::ReaderDiscoveryInfo::REMOVED_READER) {
    remove(info.info.guid());
  } else {
    add(info.info.guid(), info.info.topicName().to_string(), info.info.typeName().to_string(), false);
  }
}

void DiscoveryMap::add(const rtps::GUID_t& guid, const std::string& topic, const std::string& type, bool is_writer) {
  std::lock_guard lock(mutex_);
  endpoints_[guid] = Endpoint{topic, type, is_writer};
}

void DiscoveryMap::remove(const rtps::GUID_t& guid) {
  std::lock_guard lock(mutex_);
  endpoints_.erase(guid);
}

std::vector<DiscoveredTopic> DiscoveryMap::topics() const {
  std::map<std::pair<std::string, std::string>, DiscoveredTopic> by_name_and_type;
  {
    std::lock_guard lock(mutex_);
    for (const auto& [guid, endpoint] : endpoints_) {
      auto& topic = by_name_and_type[{endpoint.topic, endpoint.type}];
      topic.name = endpoint.topic;
      topic.type_name = endpoint.type;
      (endpoint.is_writer ? topic.writers : topic.readers) += 1;
    }
  }
  std::vector<DiscoveredTopic> result;
  for (auto& [key, topic] : by_name_and_type) result.push_back(std::move(topic));
  return result;
}

ParticipantState::ParticipantState(const ParticipantOptions& options) : secured_(!options.security.empty()) {
  const dds::DomainParticipantQos qos = participant_qos(options);
  auto* factory = dds::DomainParticipantFactory::get_instance();
  // Only endpoint discovery is of interest; participant-level callbacks stay off.
  dds::StatusMask mask = dds::StatusMask::none();
  participant_ = factory->create_participant(options.domain_id, qos, &discovery_, mask);
  if (participant_ == nullptr) {
    throw Error("Fast DDS could not create a participant on domain " + std::to_string(options.domain_id));
  }
  publisher_ = participant_->create_publisher(dds::PUBLISHER_QOS_DEFAULT);
  subscriber_ = participant_->create_subscriber(dds::SUBSCRIBER_QOS_DEFAULT);
  if (publisher_ == nullptr || subscriber_ == nullptr) {
    participant_->delete_contained_entities();
    factory->delete_participant(participant_);
    throw Error("Fast DDS could not create a publisher and a subscriber");
  }
}

ParticipantState::~ParticipantState() {
  // Writers and readers are gone (each holds this state); what remains are the topics.
  participant_->set_listener(nullptr);
  participant_->delete_contained_entities();
  // A secured participant's farewell goes out on plain discovery, which Cyclone DDS refuses for an
  // authenticated peer ("SPDP ST3 ... not allowed"): a Cyclone participant keeps this one until its
  // lease ends, repeating what this one never acknowledged, its key-exchange messages. Those repeats
  // go to this participant's port, where the next plumb command of this host (same participant
  // index) cannot decode them, drops the whole datagram with its own messages in it, and is not
  // answered until the lease ends (30 s; security_component_cyclonedds_fastdds, docs/security.md).
  // Cyclone repeats them every 100 ms until acknowledged: staying 300 ms acknowledges them.
  if (secured_) std::this_thread::sleep_for(std::chrono::milliseconds(300));
  dds::DomainParticipantFactory::get_instance()->delete_participant(participant_);
}

dds::Topic* ParticipantState::topic(const TypeSupport& type, const std::string& name) {
  // Caller holds entity_mutex_.
  const std::string type_name = type.type_name;
  if (dds::TopicDescription* existing = participant_->lookup_topicdescription(name)) {
    if (existing->get_type_name() != type_name) {
      throw Error("topic " + name + " already exists here with type " + existing->get_type_name() + ", not " + type_name);
    }
    return static_cast<dds::Topic*>(existing);
  }
  // fastddsgen registers the scoped IDL name ("plumb::msg::Attitude"), the same string Cyclone uses.
  if (participant_->find_type(type_name).empty() &&
      dds::TypeSupport(find_type(type).make_data_type()).register_type(participant_) != ReturnCode_t::RETCODE_OK) {
    throw Error("Fast DDS could not register type " + type_name);
  }
  dds::Topic* topic = participant_->create_topic(name, type_name, dds::TOPIC_QOS_DEFAULT);
  if (topic == nullptr) throw Error("Fast DDS could not create topic " + name);
  return topic;
}

}  // namespace plumb::transport::fastdds
