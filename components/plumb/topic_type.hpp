// Resolving what type a topic carries, and calling generic code with that type.
#pragma once

#include <string>

#include "plumb/transport/topic_names.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::cli {

// Calls f(T{}) with the topics:: type of `type`.
template <class F> decltype(auto) with_topic_type(transport::TopicType type, F&& f) {
  using transport::TopicType;
  switch (type) {
    case TopicType::SensorBatch: return f(topics::SensorBatch{});
    case TopicType::Attitude: return f(topics::Attitude{});
    case TopicType::CalibrationCoefficients: return f(topics::CalibrationCoefficients{});
    case TopicType::ComponentStatus: return f(topics::ComponentStatus{});
    case TopicType::Truth: return f(topics::Truth{});
  }
  throw transport::Error("unknown topic type");
}

// The type of `topic`: by plumb's naming convention, else from what discovery reports within
// `discovery_s` seconds. Throws transport::Error "unknown topic ..." listing what is known.
transport::TopicType resolve_topic_type(transport::Participant& participant, const std::string& topic, double discovery_s);

}  // namespace plumb::cli
