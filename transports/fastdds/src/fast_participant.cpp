#include "fast_participant.hpp"

#include "fast_reader.hpp"
#include "fast_writer.hpp"

namespace plumb::transport::fastdds {

namespace {
void check_topic_name(const std::string& topic) {
  if (topic.empty()) throw Error("a topic name must not be empty");
}
}  // namespace

FastParticipant::FastParticipant(const ParticipantOptions& options)
    : state_(std::make_shared<ParticipantState>(options)) {}

std::unique_ptr<RawWriter> FastParticipant::create_writer(const TypeSupport& type, const std::string& topic, const Qos& qos) {
  check_topic_name(topic);
  return std::make_unique<FastWriter>(state_, type, topic, qos);
}

std::unique_ptr<RawReader> FastParticipant::create_reader(const TypeSupport& type, const std::string& topic, const Qos& qos,
                                                          std::function<void()> on_data) {
  check_topic_name(topic);
  return std::make_unique<FastReader>(state_, type, topic, qos, std::move(on_data));
}

std::vector<DiscoveredTopic> FastParticipant::discovered_topics() { return state_->discovery().topics(); }

}  // namespace plumb::transport::fastdds
