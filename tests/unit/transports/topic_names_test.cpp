// The topic table generated from the `// @topic` lines of idl/: type and QoS follow from the name.
#include <gtest/gtest.h>

#include "plumb/transport/topic_names.hpp"

namespace {

using namespace plumb;
using namespace plumb::transport;
namespace names = topic_names;

template <class T> const TypeSupport* type() { return &topics::type_support<T>(); }

bool carries(const std::string& topic, const TypeSupport* expected) {
  const TypeSupport* t = topic_type_for(topic);
  return t != nullptr && *t == *expected;
}

TEST(TopicNames, TypeFollowsTheName) {
  EXPECT_TRUE(carries(names::kSensorRaw, type<topics::SensorBatch>()));
  EXPECT_TRUE(carries(names::kSensorCalibrated, type<topics::SensorBatch>()));
  EXPECT_TRUE(carries(names::attitude("compensated"), type<topics::Attitude>()));
  EXPECT_TRUE(carries(names::kCalibration, type<topics::CalibrationCoefficients>()));
  EXPECT_TRUE(carries(names::kStatus, type<topics::ComponentStatus>()));
  EXPECT_TRUE(carries(names::kSimTruth, type<topics::Truth>()));
  EXPECT_EQ(topic_type_for("plumb/attitude/"), nullptr);  // no estimator name
  EXPECT_EQ(topic_type_for("rt/chatter"), nullptr);
  EXPECT_EQ(topic_type_for(""), nullptr);
}

TEST(TopicNames, NavigatorTopicsAreDeclaredInTheIdl) {
  EXPECT_TRUE(carries(names::navigation("strapdown"), type<topics::Navigation>()));
  EXPECT_EQ(names::navigation("strapdown"), "plumb/navigation/strapdown");
  EXPECT_TRUE(carries(names::kDepth, type<topics::MeasuredDepth>()));
  for (const char* topic : {"plumb/navigation/strapdown", "plumb/depth"}) {
    const Qos qos = default_qos_for_topic(topic);
    EXPECT_EQ(qos.reliability, Reliability::Reliable) << topic;
    EXPECT_EQ(qos.durability, Durability::Volatile) << topic;
    EXPECT_EQ(qos.history, History::KeepLast) << topic;
    EXPECT_EQ(qos.depth, 64) << topic;
  }
}

// The survey of a tool is kept whole for late joiners.
TEST(TopicNames, SurveyTopicKeepsEveryStationForLateJoiners) {
  EXPECT_EQ(names::survey("drill"), "plumb/survey/drill");
  EXPECT_TRUE(carries(names::survey("drill"), type<topics::SurveyStation>()));
  const Qos qos = default_qos_for_topic(names::survey("drill"));
  EXPECT_EQ(qos.reliability, Reliability::Reliable);
  EXPECT_EQ(qos.durability, Durability::TransientLocal);
  EXPECT_EQ(qos.history, History::KeepAll);
  EXPECT_STREQ(type<topics::SurveyStation>()->type_name, "plumb::msg::SurveyStation");
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

TEST(TopicNames, TheTableMatchesTheFormerQosProfiles) {
  auto same = [](const Qos& a, const Qos& b) {
    return a.reliability == b.reliability && a.durability == b.durability && a.history == b.history && a.depth == b.depth;
  };
  EXPECT_TRUE(same(default_qos_for_topic(names::kSensorRaw), Qos::sensor_stream()));
  EXPECT_TRUE(same(default_qos_for_topic(names::sensor("other")), Qos::sensor_stream()));
  EXPECT_TRUE(same(default_qos_for_topic(names::attitude("x")), Qos::attitude()));
  EXPECT_TRUE(same(default_qos_for_topic(names::kCalibration), Qos::calibration()));
  // Status: the table is the readers' QoS; writers keep only their last report (Qos::status()).
  const Qos status_readers = default_qos_for_topic(names::kStatus);
  EXPECT_EQ(status_readers.durability, Durability::TransientLocal);
  EXPECT_TRUE(same(status_readers, {Reliability::Reliable, Durability::TransientLocal, History::KeepLast, 32}));
  EXPECT_TRUE(same(Qos::status(), {Reliability::Reliable, Durability::TransientLocal, History::KeepLast, 1}));
  EXPECT_TRUE(same(default_qos_for_topic(names::kSimTruth), Qos::attitude()));
}

TEST(TopicNames, TypeNamesAreTheScopedIdlNames) {
  EXPECT_STREQ(type<topics::SensorBatch>()->type_name, "plumb::msg::SensorBatch");
  EXPECT_STREQ(type<topics::Attitude>()->type_name, "plumb::msg::Attitude");
  EXPECT_STREQ(type<topics::CalibrationCoefficients>()->type_name, "plumb::msg::CalibrationCoefficients");
  EXPECT_STREQ(type<topics::ComponentStatus>()->type_name, "plumb::msg::ComponentStatus");
  EXPECT_STREQ(type<topics::Truth>()->type_name, "plumb::msg::Truth");
  EXPECT_STREQ(type<topics::Navigation>()->type_name, "plumb::msg::Navigation");
  EXPECT_STREQ(type<topics::MeasuredDepth>()->type_name, "plumb::msg::MeasuredDepth");
  for (const TypeSupport* t : topics::kAllTypes) EXPECT_EQ(topics::find_type_support(t->type_name), t);
  EXPECT_EQ(topics::find_type_support("plumb::msg::NoSuchType"), nullptr);
}

}  // namespace
