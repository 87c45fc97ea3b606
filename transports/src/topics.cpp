// Type names and the per-topic conventions shared by every transport plugin and every component.
#include <string_view>

#include "plumb/transport/topic_names.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::transport {

namespace {
bool has_prefix(std::string_view text, std::string_view prefix) {
  return text.size() > prefix.size() && text.substr(0, prefix.size()) == prefix;
}
}  // namespace

const char* type_name(TopicType type) {
  // Scoped IDL names: both vendors register the type under exactly this string, so a Fast DDS
  // writer and a Cyclone DDS reader match.
  switch (type) {
    case TopicType::SensorBatch: return "plumb::msg::SensorBatch";
    case TopicType::Attitude: return "plumb::msg::Attitude";
    case TopicType::CalibrationCoefficients: return "plumb::msg::CalibrationCoefficients";
    case TopicType::ComponentStatus: return "plumb::msg::ComponentStatus";
    case TopicType::Truth: return "plumb::msg::Truth";
  }
  return "unknown";
}

std::string topic_names::attitude(const std::string& estimator) { return std::string(kAttitudePrefix) + estimator; }

std::optional<TopicType> topic_type_for(const std::string& topic) {
  if (has_prefix(topic, topic_names::kSensorPrefix)) return TopicType::SensorBatch;
  if (has_prefix(topic, topic_names::kAttitudePrefix)) return TopicType::Attitude;
  if (topic == topic_names::kCalibration) return TopicType::CalibrationCoefficients;
  if (topic == topic_names::kStatus) return TopicType::ComponentStatus;
  if (topic == topic_names::kSimTruth) return TopicType::Truth;
  return std::nullopt;
}

Qos default_qos_for_topic(const std::string& topic) {
  if (has_prefix(topic, topic_names::kSensorPrefix)) return Qos::sensor_stream();
  if (has_prefix(topic, topic_names::kAttitudePrefix)) return Qos::attitude();
  if (topic == topic_names::kCalibration) return Qos::calibration();
  if (topic == topic_names::kStatus) return Qos::status();
  // Truth and unknown topics: reliable, volatile, like attitude.
  return Qos::attitude();
}

}  // namespace plumb::transport
