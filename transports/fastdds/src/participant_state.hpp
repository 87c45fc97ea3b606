// Everything one Fast DDS participant owns: the DomainParticipant with its one publisher and one
// subscriber, the topics created on it, and what discovery reported. Writers and readers hold a
// shared_ptr to it, so the participant is deleted only after the last of its endpoints, whatever
// order the user drops the handles in.
#pragma once

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::fastdds {

// Endpoints seen through discovery, by GUID, so that a removed endpoint is counted out again.
class DiscoveryMap final : public eprosima::fastdds::dds::DomainParticipantListener {
 public:
  void on_publisher_discovery(eprosima::fastdds::dds::DomainParticipant* participant,
                              eprosima::fastrtps::rtps::WriterDiscoveryInfo&& info) override;
  void on_subscriber_discovery(eprosima::fastdds::dds::DomainParticipant* participant,
                               eprosima::fastrtps::rtps::ReaderDiscoveryInfo&& info) override;

  void add(const eprosima::fastrtps::rtps::GUID_t& guid, const std::string& topic, const std::string& type, bool is_writer);
  void remove(const eprosima::fastrtps::rtps::GUID_t& guid);
  std::vector<DiscoveredTopic> topics() const;

 private:
  struct Endpoint {
    std::string topic;
    std::string type;
    bool is_writer = false;
  };
  mutable std::mutex mutex_;
  std::map<eprosima::fastrtps::rtps::GUID_t, Endpoint> endpoints_;
};

class ParticipantState {
 public:
  explicit ParticipantState(const ParticipantOptions& options);  // throws Error
  ~ParticipantState();
  ParticipantState(const ParticipantState&) = delete;
  ParticipantState& operator=(const ParticipantState&) = delete;

  // The topic `name` of `type`, created on first use; Error if it exists with another type.
  eprosima::fastdds::dds::Topic* topic(const TypeSupport& type, const std::string& name);

  eprosima::fastdds::dds::DomainParticipant& participant() { return *participant_; }
  eprosima::fastdds::dds::Publisher& publisher() { return *publisher_; }
  eprosima::fastdds::dds::Subscriber& subscriber() { return *subscriber_; }
  DiscoveryMap& discovery() { return discovery_; }
  // Serialises creation and deletion of entities on this participant.
  std::mutex& entity_mutex() { return entity_mutex_; }

 private:
  DiscoveryMap discovery_;  // declared first: it must outlive the participant that calls it
  std::mutex entity_mutex_;
  eprosima::fastdds::dds::DomainParticipant* participant_ = nullptr;
  eprosima::fastdds::dds::Publisher* publisher_ = nullptr;
  eprosima::fastdds::dds::Subscriber* subscriber_ = nullptr;
  bool secured_ = false;
};

}  // namespace plumb::transport::fastdds
