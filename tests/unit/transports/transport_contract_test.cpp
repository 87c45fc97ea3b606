// What every transport plugin must do, checked on each vendor that is built: refuse bad domain
// ids and oversize messages with transport::Error, and carry a message within one process.
#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <map>
#include <string>
#include <vector>
#include <chrono>
#include <thread>

#include "plumb/transport/loader.hpp"
#include "plumb/transport/topic_names.hpp"
#include "test_messages.hpp"

namespace {

using namespace plumb;
using namespace plumb::transport;
using namespace std::chrono_literals;
namespace names_for_status_test = plumb::transport::topic_names;

class TransportContract : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { transport_ = load_transport(GetParam()); }

  // A domain of its own per vendor, and topic names of its own per process, so that test
  // processes running in parallel never see each other's messages.
  std::unique_ptr<Participant> participant() {
    ParticipantOptions options;
    options.domain_id = GetParam() == "cyclonedds" ? 201 : 202;
    options.name = "plumb-transport-contract-test";
    return transport_->create_participant(options);
  }
  static std::string topic(const std::string& base) { return base + "_" + std::to_string(getpid()); }

  std::shared_ptr<Transport> transport_;
};

TEST_P(TransportContract, NamesItselfAndItsVendor) {
  EXPECT_EQ(transport_->name(), GetParam());
  EXPECT_FALSE(transport_->vendor_version().empty());
}

TEST_P(TransportContract, RefusesDomainIdsOutsideZeroTo232) {
  for (int id : {-1, 233, 1000}) {
    ParticipantOptions options;
    options.domain_id = id;
    EXPECT_THROW(transport_->create_participant(options), Error) << id;
  }
}

TEST_P(TransportContract, RefusesAnInterfaceThisHostDoesNotHave) {
  ParticipantOptions options;
  options.domain_id = 203;
  options.interface = "plumbnosuch0";
  EXPECT_THROW(transport_->create_participant(options), Error);
}

TEST_P(TransportContract, AcceptsLoopbackByNameAndAddress) {
  for (const char* interface : {"lo", "127.0.0.1"}) {
    ParticipantOptions options;
    options.domain_id = 203;
    options.interface = interface;
    EXPECT_NO_THROW(transport_->create_participant(options)) << interface;
  }
}

TEST_P(TransportContract, RefusesStringsLongerThanTheirIdlBound) {
  auto p = participant();
  auto writer = make_writer<topics::Attitude>(*p, topic("plumb/attitude/bounds"), Qos::attitude());
  topics::Attitude a;
  a.tool_id = std::string(topics::Attitude::kToolIdMax, 'x');
  a.estimator = std::string(topics::Counter::kNameMax, 'y');
  a.reason = std::string(topics::Attitude::kReasonMax, 'z');
  EXPECT_NO_THROW(writer.write(a));  // exactly at the bound is fine
  for (auto field : {&topics::Attitude::tool_id, &topics::Attitude::estimator, &topics::Attitude::reason}) {
    topics::Attitude longer = a;
    (longer.*field) += "!";
    EXPECT_THROW(writer.write(longer), Error);
  }
  auto status = make_writer<topics::ComponentStatus>(*p, topic("plumb/status"), Qos::status());
  topics::ComponentStatus s;
  s.last_error = std::string(topics::ComponentStatus::kLastErrorMax + 1, 'e');
  EXPECT_THROW(status.write(s), Error);
  s.last_error.clear();
  s.counters.push_back({std::string(topics::Counter::kNameMax + 1, 'c'), 1});
  EXPECT_THROW(status.write(s), Error);
}

TEST_P(TransportContract, RefusesBatchesOverThirtyTwoSamples) {
  auto p = participant();
  auto writer = make_writer<topics::SensorBatch>(*p, topic("plumb/sensor/bounds"), Qos::sensor_stream());
  topics::SensorBatch batch;
  batch.samples.resize(topics::SensorBatch::kSamplesMax);
  EXPECT_NO_THROW(writer.write(batch));
  batch.samples.resize(topics::SensorBatch::kSamplesMax + 1);
  EXPECT_THROW(writer.write(batch), Error);

  auto status = make_writer<topics::ComponentStatus>(*p, topic("plumb/status_bounds"), Qos::status());
  topics::ComponentStatus s;
  s.counters.resize(topics::ComponentStatus::kCountersMax + 1);
  EXPECT_THROW(status.write(s), Error);
}

TEST_P(TransportContract, WaitReturnsFalseWhenNothingArrives) {
  auto p = participant();
  auto reader = make_reader<topics::Truth>(*p, topic("plumb/sim/quiet"), Qos::attitude());
  EXPECT_FALSE(reader.wait(10ms));
  topics::Truth t;
  EXPECT_FALSE(reader.take(t));
}

// Bounded waits only: the test fails by missing data, never by being slow.
template <class T> bool receive(Reader<T>& reader, T& message, std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    if (reader.take(message)) return true;
    reader.wait(100ms);
  }
  return false;
}

TEST_P(TransportContract, CarriesEveryFieldWithinOneProcessAndCallsOnData) {
  auto p = participant();
  const std::string name = topic("plumb/attitude/roundtrip");
  std::atomic<int> callbacks{0};
  auto reader = make_reader<topics::Attitude>(*p, name, Qos::attitude(), [&] { ++callbacks; });
  auto writer = make_writer<topics::Attitude>(*p, name, Qos::attitude());
  for (int i = 0; i < 100 && writer.matched_readers() == 0; ++i) std::this_thread::sleep_for(50ms);
  ASSERT_EQ(writer.matched_readers(), 1u);
  EXPECT_EQ(reader.matched_writers(), 1u);
  const topics::Attitude sent = test::full_attitude();
  writer.write(sent);
  topics::Attitude got;
  ASSERT_TRUE(receive(reader, got, 10s));
  EXPECT_EQ(test::first_difference(sent, got), "");
  EXPECT_EQ(sent, got);
  EXPECT_GE(callbacks.load(), 1);
  EXPECT_FALSE(reader.take(got));  // exactly one message
}

TEST_P(TransportContract, KeepsCalibrationForALateReader) {
  auto p = participant();
  const std::string name = topic("plumb/calibration");
  auto writer = make_writer<topics::CalibrationCoefficients>(*p, name, Qos::calibration());
  const topics::CalibrationCoefficients sent = test::full_calibration();
  writer.write(sent);
  auto reader = make_reader<topics::CalibrationCoefficients>(*p, name, Qos::calibration());
  topics::CalibrationCoefficients got;
  ASSERT_TRUE(receive(reader, got, 10s));
  EXPECT_EQ(sent, got);
}

// plumb/status is a state: a monitor that joins late gets the last report of every writer (and
// only the last: writers keep_last 1), not only the next one.
TEST_P(TransportContract, KeepsTheLastStatusOfEachWriterForALateReader) {
  auto p = participant();
  const std::string name = topic("plumb/status");
  auto first = make_writer<topics::ComponentStatus>(*p, name, Qos::status());
  auto second = make_writer<topics::ComponentStatus>(*p, name, Qos::status());
  topics::ComponentStatus s;
  for (const char* state : {"starting", "running"}) {
    s.state = state;
    s.component = "first";
    first.write(s);
    s.component = "second";
    second.write(s);
  }
  auto reader = make_reader<topics::ComponentStatus>(*p, name, default_qos_for_topic(names_for_status_test::kStatus));
  std::map<std::string, std::vector<std::string>> states;  // component -> the states it got, in order
  topics::ComponentStatus got;
  for (int i = 0; i < 2 && receive(reader, got, 10s); ++i) states[got.component].push_back(got.state);
  while (reader.wait(200ms) && reader.take(got)) states[got.component].push_back(got.state);
  EXPECT_EQ(states["first"], std::vector<std::string>{"running"});
  EXPECT_EQ(states["second"], std::vector<std::string>{"running"});
}

// A writer's last words: with no reader, or once the reader has the sample, the wait ends with true.
TEST_P(TransportContract, WaitsForAcknowledgmentsOfMatchedReaders) {
  auto p = participant();
  const std::string name = topic("plumb/status_acks");
  auto writer = make_writer<topics::ComponentStatus>(*p, name, Qos::status());
  topics::ComponentStatus s;
  s.state = "stopping";
  writer.write(s);
  EXPECT_TRUE(writer.wait_for_acknowledgments(1s));
  auto reader = make_reader<topics::ComponentStatus>(*p, name, default_qos_for_topic(names_for_status_test::kStatus));
  for (int i = 0; i < 100 && writer.matched_readers() == 0; ++i) std::this_thread::sleep_for(50ms);
  ASSERT_EQ(writer.matched_readers(), 1u);
  writer.write(s);
  EXPECT_TRUE(writer.wait_for_acknowledgments(5s));
  topics::ComponentStatus got;
  ASSERT_TRUE(receive(reader, got, 10s));
  EXPECT_EQ(got.state, "stopping");
}

TEST_P(TransportContract, DiscoversItsOwnTopicsWithTheirTypeNames) {
  auto p = participant();
  const std::string name = topic("plumb/sim/discovered");
  auto writer = make_writer<topics::Truth>(*p, name, Qos::attitude());
  std::vector<DiscoveredTopic> topics;
  auto has_topic = [&] {
    topics = p->discovered_topics();
    for (const auto& t : topics) if (t.name == name) return true;
    return false;
  };
  for (int i = 0; i < 100 && !has_topic(); ++i) std::this_thread::sleep_for(50ms);
  ASSERT_TRUE(has_topic());
  for (const auto& t : topics) {
    if (t.name != name) continue;
    EXPECT_EQ(t.type_name, "plumb::msg::Truth");
    EXPECT_EQ(t.writers, 1u);
    EXPECT_EQ(t.readers, 0u);
  }
}

TEST_P(TransportContract, RefusesATypeItWasNotBuiltWith) {
  auto p = participant();
  const TypeSupport unknown{"plumb::msg::NoSuchType", 1};
  EXPECT_THROW(p->create_writer(unknown, topic("plumb/nosuch"), Qos::attitude()), Error);
  // Same name, other layout: a plugin built from other IDL must not misread the message.
  const TypeSupport other_layout{"plumb::msg::Attitude", topics::type_support<topics::Attitude>().layout_hash + 1};
  EXPECT_THROW(p->create_reader(other_layout, topic("plumb/attitude/layout"), Qos::attitude()), Error);
}

INSTANTIATE_TEST_SUITE_P(Vendors, TransportContract, ::testing::Values(PLUMB_BUILT_TRANSPORTS),
                         [](const auto& info) { return info.param; });

}  // namespace
