// A Participant on Fast DDS: a thin handle on the shared ParticipantState.
#pragma once

#include <memory>

#include "participant_state.hpp"

namespace plumb::transport::fastdds {

class FastParticipant final : public Participant {
 public:
  explicit FastParticipant(const ParticipantOptions& options);

  std::unique_ptr<RawWriter> create_writer(const TypeSupport& type, const std::string& topic, const Qos& qos) override;
  std::unique_ptr<RawReader> create_reader(const TypeSupport& type, const std::string& topic, const Qos& qos,
                                           std::function<void()> on_data) override;
  std::vector<DiscoveredTopic> discovered_topics() override;

 private:
  std::shared_ptr<ParticipantState> state_;
};

}  // namespace plumb::transport::fastdds
