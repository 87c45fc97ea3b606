#include "messages/topic_type.hpp"

#include <chrono>
#include <thread>

#include "plumb/components/topic_wait.hpp"
#include "plumb/core/edit_distance.hpp"

namespace plumb::cli {

namespace {
std::string known_names() {
  std::string names;
  for (const auto& e : topics::kTopicTable) {
    names += (names.empty() ? "" : ", ") + std::string(e.name) + (e.prefix ? "<name>" : "");
  }
  return names;
}
}  // namespace

const transport::TypeSupport& resolve_topic_type(transport::Participant& participant, const std::string& topic,
                                                 double discovery_s) {
  if (const auto* t = transport::topic_type_for(topic)) return *t;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(discovery_s);
  do {
    for (const auto& d : participant.discovered_topics()) {
      if (d.name != topic) continue;
      if (const auto* t = topics::find_type_support(d.type_name)) return *t;
      throw transport::Error("topic '" + topic + "' carries type '" + d.type_name + "', which is not a plumb type");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  } while (std::chrono::steady_clock::now() < deadline);
  const std::string hint = did_you_mean(components::closest_topic_names(participant, topic));
  throw transport::Error("unknown topic '" + topic + "': " + (hint.empty() ? "" : hint + " (") + "not a plumb topic name (" +
                         known_names() + ") and not seen on the network" + (hint.empty() ? "" : ")"));
}

}  // namespace plumb::cli
