#include "topic_type.hpp"

#include <chrono>
#include <thread>

namespace plumb::cli {
namespace topic_names = transport::topic_names;

transport::TopicType resolve_topic_type(transport::Participant& participant, const std::string& topic, double discovery_s) {
  if (auto t = transport::topic_type_for(topic)) return *t;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(discovery_s);
  do {
    for (const auto& d : participant.discovered_topics()) {
      if (d.name != topic) continue;
      for (auto type : transport::kAllTopicTypes) {
        if (d.type_name == transport::type_name(type)) return type;
      }
      throw transport::Error("topic '" + topic + "' carries type '" + d.type_name + "', which is not a plumb type");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  } while (std::chrono::steady_clock::now() < deadline);
  throw transport::Error("unknown topic '" + topic + "': not a plumb topic name (" + topic_names::kSensorRaw + ", " +
                         topic_names::kSensorCalibrated + ", " + topic_names::kAttitudePrefix + "<estimator>, " +
                         topic_names::kCalibration + ", " + topic_names::kStatus + ", " + topic_names::kSimTruth +
                         ") and not seen on the network");
}

}  // namespace plumb::cli
