// The well-known plumb topic names and what follows from a name by convention: its type and QoS.
// Names use '/' as separator; both vendors accept it (ROS 2 topics are "rt/..." on both).
#pragma once

#include <optional>
#include <string>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::topic_names {

inline constexpr const char* kSensorRaw = "plumb/sensor/raw";
inline constexpr const char* kSensorCalibrated = "plumb/sensor/calibrated";
inline constexpr const char* kSensorPrefix = "plumb/sensor/";
inline constexpr const char* kAttitudePrefix = "plumb/attitude/";  // + estimator name
inline constexpr const char* kCalibration = "plumb/calibration";
inline constexpr const char* kStatus = "plumb/status";
inline constexpr const char* kSimTruth = "plumb/sim/truth";

// "plumb/attitude/<estimator>", the topic an estimator host publishes one plugin's estimates on.
std::string attitude(const std::string& estimator);

}  // namespace plumb::transport::topic_names

namespace plumb::transport {

// The type carried by a topic, by the naming convention above ("plumb/sensor/..." -> SensorBatch,
// "plumb/attitude/..." -> Attitude, ...); nullopt for a name outside the convention.
std::optional<TopicType> topic_type_for(const std::string& topic);

// Every topic type, for tools that go through all of them.
inline constexpr TopicType kAllTopicTypes[] = {TopicType::SensorBatch, TopicType::Attitude,
                                              TopicType::CalibrationCoefficients, TopicType::ComponentStatus,
                                              TopicType::Truth};

}  // namespace plumb::transport
