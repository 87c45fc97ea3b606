// The topic naming conventions: type and QoS follow from the name.
#include <gtest/gtest.h>

#include "plumb/transport/topic_names.hpp"

namespace {

using namespace plumb::transport;
namespace names = topic_names;

TEST(TopicNames, TypeFollowsTheName) {
  EXPECT_EQ(topic_type_for(names::kSensorRaw), TopicType::SensorBatch);
  EXPECT_EQ(topic_type_for(names::kSensorCalibrated), TopicType::SensorBatch);
  EXPECT_EQ(topic_type_for(names::attitude("compensated")), TopicType::Attitude);
  EXPECT_EQ(topic_type_for(names::kCalibration), TopicType::CalibrationCoefficients);
  EXPECT_EQ(topic_type_for(names::kStatus), TopicType::ComponentStatus);
  EXPECT_EQ(topic_type_for(names::kSimTruth), TopicType::Truth);
  EXPECT_FALSE(topic_type_for("plumb/attitude/").has_value());  // no estimator name
  EXPECT_FALSE(topic_type_for("rt/chatter").has_value());
  EXPECT_FALSE(topic_type_for("").has_value());
}

TEST(TopicNames, AttitudeTopicNamesTheEstimator) {
  EXPECT_EQ(names::attitude("static"), "plumb/attitude/static");
}

TEST(TopicNames, QosFollowsTheTable) {
  const Qos sensor = default_qos_for_topic(names::kSensorRaw);
  EXPECT_EQ(sensor.reliability, Reliability::BestEffort);
  EXPECT_EQ(sensor.history, History::KeepLast);
  EXPECT_EQ(default_qos_for_topic(names::attitude("integral")).reliability, Reliability::Reliable);
  EXPECT_EQ(default_qos_for_topic(names::kStatus).reliability, Reliability::Reliable);
  const Qos calibration = default_qos_for_topic(names::kCalibration);
  EXPECT_EQ(calibration.reliability, Reliability::Reliable);
  EXPECT_EQ(calibration.durability, Durability::TransientLocal);
  EXPECT_EQ(default_qos_for_topic("something/else").reliability, Reliability::Reliable);
}

TEST(TopicNames, TypeNamesAreTheScopedIdlNames) {
  EXPECT_STREQ(type_name(TopicType::SensorBatch), "plumb::msg::SensorBatch");
  EXPECT_STREQ(type_name(TopicType::Attitude), "plumb::msg::Attitude");
  EXPECT_STREQ(type_name(TopicType::CalibrationCoefficients), "plumb::msg::CalibrationCoefficients");
  EXPECT_STREQ(type_name(TopicType::ComponentStatus), "plumb::msg::ComponentStatus");
  EXPECT_STREQ(type_name(TopicType::Truth), "plumb::msg::Truth");
}

}  // namespace
