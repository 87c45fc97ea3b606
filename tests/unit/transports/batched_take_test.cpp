// Reader<T>::take(out, max), the batched take: every message arrives exactly once and in the order
// it was written, whatever `max` is (below, at and above the plugins' per-call chunk of 64), mixed
// with single takes, on each vendor and across vendors (both plugins loaded in this one process,
// talking over loopback like two processes would).
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <iterator>
#include <thread>
#include <tuple>

#include "plumb/transport/loader.hpp"

namespace {

using namespace plumb;
using namespace plumb::transport;
using namespace std::chrono_literals;

// Domain 205: the contract test uses 201-203; topics carry this process's id (parallel runs).
constexpr int kDomain = 205;

std::vector<std::string> built_transports() { return {PLUMB_BUILT_TRANSPORTS}; }

std::vector<std::tuple<std::string, std::string>> vendor_pairs() {
  std::vector<std::tuple<std::string, std::string>> pairs;
  for (const auto& writer : built_transports())
    for (const auto& reader : built_transports()) pairs.emplace_back(writer, reader);
  return pairs;
}

std::unique_ptr<Participant> participant(Transport& transport, const char* role) {
  ParticipantOptions options;
  options.domain_id = kDomain;
  options.name = std::string("plumb-batched-take-test-") + role;
  return transport.create_participant(options);
}

template <class Writer, class Reader> bool wait_for_match(Writer& writer, Reader& reader) {
  for (int i = 0; i < 200; ++i) {
    if (writer.matched_readers() > 0 && reader.matched_writers() > 0) return true;
    std::this_thread::sleep_for(50ms);
  }
  return false;
}

// The sequence number rides in window_start_ns (attitude) or the first sample's seq (batch).
void set_seq(topics::Attitude& m, std::uint64_t seq) { m.window_start_ns = static_cast<std::int64_t>(seq); }
std::uint64_t get_seq(const topics::Attitude& m) { return static_cast<std::uint64_t>(m.window_start_ns); }
void set_seq(topics::SensorBatch& m, std::uint64_t seq) { m.samples.at(0).seq = seq; }
std::uint64_t get_seq(const topics::SensorBatch& m) { return m.samples.at(0).seq; }

topics::Attitude prototype(topics::Attitude) {
  topics::Attitude m;
  m.tool_id = "batched-take";
  m.estimator = "test";
  return m;
}
topics::SensorBatch prototype(topics::SensorBatch) {
  topics::SensorBatch m;
  m.tool_id = "batched-take";
  m.samples.resize(topics::SensorBatch::kSamplesMax);
  return m;
}

class BatchedTake : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {
 protected:
  // Writes `count` messages as fast as write() returns; takes them back with a rotation of batch
  // sizes and single takes; returns the sequence numbers in the order they were taken.
  template <class T> std::vector<std::uint64_t> round_trip(const std::string& base, std::uint64_t count) {
    const auto& [writer_vendor, reader_vendor] = GetParam();
    auto writer_transport = load_transport(writer_vendor);
    auto reader_transport = load_transport(reader_vendor);
    auto writer_participant = participant(*writer_transport, "writer");
    auto reader_participant = participant(*reader_transport, "reader");
    const std::string name = base + "_" + writer_vendor + "_" + reader_vendor + "_" + std::to_string(getpid());
    // Reliable keep-last 4096: nothing is lost or overwritten for these counts.
    auto reader = make_reader<T>(*reader_participant, name, Qos::reliable_stream());
    auto writer = make_writer<T>(*writer_participant, name, Qos::reliable_stream());
    EXPECT_TRUE(wait_for_match(writer, reader)) << "no match " << writer_vendor << " -> " << reader_vendor;

    T message = prototype(T{});
    for (std::uint64_t seq = 0; seq < count; ++seq) {
      set_seq(message, seq);
      writer.write(message);
    }

    std::vector<std::uint64_t> taken;
    std::vector<T> batch;
    const std::size_t sizes[] = {1, 7, 64, 100, 0};  // 0: the single-message take
    std::size_t turn = 0;
    const auto deadline = std::chrono::steady_clock::now() + 20s;
    while (taken.size() < count && std::chrono::steady_clock::now() < deadline) {
      const std::size_t max = sizes[turn++ % std::size(sizes)];
      if (max == 0) {
        T one;
        if (reader.take(one)) taken.push_back(get_seq(one));
      } else {
        const std::size_t n = reader.take(batch, max);
        EXPECT_LE(n, max);
        EXPECT_EQ(n, batch.size());
        for (const T& m : batch) taken.push_back(get_seq(m));
      }
      if (taken.size() < count) reader.wait(20ms);
    }
    // Nothing more arrives afterwards: every message was taken exactly once.
    std::this_thread::sleep_for(100ms);
    EXPECT_EQ(reader.take(batch, 100), 0u);
    EXPECT_TRUE(batch.empty());
    return taken;
  }
};

std::vector<std::uint64_t> zero_to(std::uint64_t count) {
  std::vector<std::uint64_t> all(count);
  for (std::uint64_t i = 0; i < count; ++i) all[i] = i;
  return all;
}

TEST_P(BatchedTake, ReturnsEveryAttitudeOnceInOrder) {
  EXPECT_EQ(round_trip<topics::Attitude>("plumb/test/batched_attitude", 1000), zero_to(1000));
}

TEST_P(BatchedTake, ReturnsEverySensorBatchOnceInOrder) {
  EXPECT_EQ(round_trip<topics::SensorBatch>("plumb/test/batched_sensor", 300), zero_to(300));
}

TEST(BatchedTakeEmpty, ReturnsZeroAndEmptiesTheVectorWhenNothingArrived) {
  for (const auto& vendor : built_transports()) {
    auto transport = load_transport(vendor);
    auto p = participant(*transport, "empty");
    auto reader = make_reader<topics::Attitude>(*p, "plumb/test/batched_empty_" + std::to_string(getpid()), Qos::attitude());
    std::vector<topics::Attitude> out(3);
    EXPECT_EQ(reader.take(out, 10), 0u) << vendor;
    EXPECT_TRUE(out.empty()) << vendor;
  }
}

INSTANTIATE_TEST_SUITE_P(VendorPairs, BatchedTake, ::testing::ValuesIn(vendor_pairs()),
                         [](const auto& info) { return std::get<0>(info.param) + "_to_" + std::get<1>(info.param); });

}  // namespace
