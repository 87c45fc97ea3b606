#include "roles.hpp"

#include <fastdds/dds/core/LoanableSequence.hpp>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <ctime>
#include <functional>
#include <iostream>
#include <mutex>
#include <thread>
#include <vector>

#include "payloads.hpp"
#include "qos.hpp"

namespace native_fastdds {
namespace {

namespace dds = eprosima::fastdds::dds;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

constexpr auto kMatchTimeout = 15s;
constexpr std::uint64_t kWarmupRoundTrips = 200;
constexpr std::int32_t kSamplesPerTake = 64;

Clock::duration seconds_of(double seconds) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

// CPU time of this whole process (all threads), as plumb-bench-transport's roles report it.
double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0;
  const auto index = static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(index), values.end());
  return values[index];
}

// Calls `on_data` from Fast DDS's listener thread when data is available, until close(). close()
// waits for a callback in progress, so that a role can return (and its locals, which the callback
// uses, go away) safely: Fast DDS's set_listener(nullptr) does not wait for one.
class Listener final : public dds::DataReaderListener {
 public:
  explicit Listener(std::function<void(dds::DataReader&)> on_data) : on_data_(std::move(on_data)) {}
  void on_data_available(dds::DataReader* reader) override {
    std::lock_guard lock(mutex_);
    if (!closed_) on_data_(*reader);
  }
  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }

 private:
  std::mutex mutex_;
  bool closed_ = false;
  std::function<void(dds::DataReader&)> on_data_;
};

// Takes batches of valid samples into sequences it owns (allocated once) and hands each to `use`,
// until the reader is empty. Not loaned: with loans, Fast DDS 2.9 crashed now and then in
// DataReaderImpl::read_or_take when a take in the listener met fragmented samples being assembled
// (SensorBatch from Cyclone DDS); plumb's plugin takes the same way.
template <class T> class Taker {
 public:
  Taker() {
    samples_.length(kSamplesPerTake);
    infos_.length(kSamplesPerTake);
  }
  template <class Use> void take_all(dds::DataReader& reader, Use&& use) {
    for (;;) {
      samples_.length(0);  // Fast DDS appends after the current length of an owned sequence
      infos_.length(0);
      if (reader.take(samples_, infos_, kSamplesPerTake) != ReturnCode_t::RETCODE_OK) return;
      for (dds::LoanableCollection::size_type i = 0; i < samples_.length(); ++i) {
        if (infos_[i].valid_data) use(samples_[i]);
      }
      if (samples_.length() < kSamplesPerTake) return;  // the reader is empty: no second, empty take
    }
  }

 private:
  dds::LoanableSequence<T> samples_;
  dds::SampleInfoSeq infos_;
};

// One participant with one publisher and one subscriber; deletes everything it created.
class Entities {
 public:
  Entities(int domain_id, dds::TopicDataType* type, const char* name) {
    auto* factory = dds::DomainParticipantFactory::get_instance();
    participant_ = factory->create_participant(domain_id, loopback_participant_qos(name));
    if (participant_ == nullptr) throw std::runtime_error("cannot create a participant");
    dds::TypeSupport(type).register_type(participant_);
    type_name_ = type->getName();
    publisher_ = participant_->create_publisher(dds::PUBLISHER_QOS_DEFAULT);
    subscriber_ = participant_->create_subscriber(dds::SUBSCRIBER_QOS_DEFAULT);
  }
  ~Entities() {
    silence();
    participant_->delete_contained_entities();
    dds::DomainParticipantFactory::get_instance()->delete_participant(participant_);
  }
  Entities(const Entities&) = delete;
  Entities& operator=(const Entities&) = delete;

  dds::DataWriter* writer(const char* topic, std::int32_t depth) {
    auto* w = publisher_->create_datawriter(find_topic(topic), writer_qos(depth));
    if (w == nullptr) throw std::runtime_error(std::string("cannot create a writer on ") + topic);
    return w;
  }
  dds::DataReader* reader(const char* topic, std::int32_t depth, Listener* listener) {
    auto* r = subscriber_->create_datareader(find_topic(topic), reader_qos(depth), listener,
                                             dds::StatusMask::data_available());
    if (r == nullptr) throw std::runtime_error(std::string("cannot create a reader on ") + topic);
    readers_.push_back(r);
    return r;
  }
  // Deletes every reader, so that no vendor thread calls their listeners any more (close the
  // listeners first: a callback in progress is waited for there).
  void silence() {
    for (auto* reader : readers_) {
      reader->set_listener(nullptr);
      subscriber_->delete_datareader(reader);
    }
    readers_.clear();
  }

 private:
  dds::Topic* find_topic(const char* name) {
    if (auto* existing = participant_->find_topic(name, eprosima::fastrtps::Duration_t(0, 0))) return existing;
    auto* topic = participant_->create_topic(name, type_name_, dds::TOPIC_QOS_DEFAULT);
    if (topic == nullptr) throw std::runtime_error(std::string("cannot create topic ") + name);
    return topic;
  }

  dds::DomainParticipant* participant_ = nullptr;
  dds::Publisher* publisher_ = nullptr;
  dds::Subscriber* subscriber_ = nullptr;
  std::string type_name_;
  std::vector<dds::DataReader*> readers_;
};

bool writer_matched(dds::DataWriter& writer) {
  dds::PublicationMatchedStatus status;
  writer.get_publication_matched_status(status);
  return status.current_count > 0;
}
bool reader_matched(dds::DataReader& reader) {
  dds::SubscriptionMatchedStatus status;
  reader.get_subscription_matched_status(status);
  return status.current_count > 0;
}

template <class Ready> bool wait_until(Ready&& ready) {
  const auto deadline = Clock::now() + kMatchTimeout;
  while (!ready()) {
    if (Clock::now() > deadline) return false;
    std::this_thread::sleep_for(10ms);
  }
  return true;
}

template <class T> int run_ping(Entities& entities, double seconds) {
  T message;
  fill(message);
  dds::DataWriter* writer = entities.writer("plumb/bench/ping", kLatencyDepth);
  std::mutex mutex;
  std::condition_variable done_cv;
  std::vector<double> one_way_us;
  std::uint64_t seq = 0;
  Clock::time_point sent_at, measure_until = Clock::time_point::max();
  bool finished = false;
  double cpu_start = 0, cpu_end = 0;  // over the measured round trips
  // The next ping leaves from this listener, as in ddsperf's listener mode and plumb's ping.
  Taker<T> taker;
  Listener listener([&](dds::DataReader& reader) {
    taker.take_all(reader, [&](const T& pong) {
      const auto now = Clock::now();
      std::lock_guard lock(mutex);
      if (finished || get_seq(pong) != seq) return;
      if (seq >= kWarmupRoundTrips) {
        one_way_us.push_back(std::chrono::duration<double, std::micro>(now - sent_at).count() / 2);
      } else if (seq + 1 == kWarmupRoundTrips) {
        measure_until = now + seconds_of(seconds);
        cpu_start = process_cpu_s();
      }
      if (now >= measure_until) {
        cpu_end = process_cpu_s();
        finished = true;
        done_cv.notify_all();
        return;
      }
      set_seq(message, ++seq);
      sent_at = Clock::now();
      writer->write(&message);
    });
  });
  dds::DataReader* reader = entities.reader("plumb/bench/pong", kLatencyDepth, &listener);
  if (!wait_until([&] { return writer_matched(*writer) && reader_matched(*reader); })) {
    std::cerr << "ping: the pong process was not discovered" << std::endl;
    listener.close();
    entities.silence();
    return 1;
  }
  std::unique_lock lock(mutex);
  set_seq(message, seq);
  sent_at = Clock::now();
  writer->write(&message);
  // Watchdog: resend the current ping when nothing moved for a while (a ping sent before the pong's
  // reader matched may only be repaired by a later heartbeat).
  const auto give_up = Clock::now() + seconds_of(seconds + 20);
  std::uint64_t last_seq = 0;
  while (!done_cv.wait_for(lock, 500ms, [&] { return finished; })) {
    if (Clock::now() > give_up) {
      std::cerr << "ping: stalled after " << seq << " round trips" << std::endl;
      finished = true;
      break;
    }
    if (seq == last_seq) {
      sent_at = Clock::now();
      writer->write(&message);
    }
    last_seq = seq;
  }
  T stop;
  fill(stop);
  set_seq(stop, kStopSeq);
  writer->write(&stop);
  lock.unlock();
  listener.close();
  entities.silence();
  std::this_thread::sleep_for(100ms);  // let the stop message go out before the writer is deleted
  if (one_way_us.empty()) return 1;
  std::printf("RESULT count=%zu median_us=%.3f p99_us=%.3f cpu_us=%.3f\n", one_way_us.size(), percentile(one_way_us, 0.5),
              percentile(one_way_us, 0.99), (cpu_end - cpu_start) * 1e6 / static_cast<double>(one_way_us.size()));
  std::fflush(stdout);  // before the teardown of the vendor entities
  return 0;
}

template <class T> int run_pong(Entities& entities, double seconds) {
  dds::DataWriter* writer = entities.writer("plumb/bench/pong", kLatencyDepth);
  std::mutex mutex;
  std::condition_variable done_cv;
  bool stopped = false;
  std::atomic<std::uint64_t> echoed{0};
  double cpu_start = 0, cpu_end = 0;  // from the first echo to the stop message (listener only)
  // Echoes every ping straight from the taken sample.
  Taker<T> taker;
  Listener listener([&](dds::DataReader& reader) {
    taker.take_all(reader, [&](const T& ping) {
      if (get_seq(ping) == kStopSeq) {
        std::lock_guard lock(mutex);
        cpu_end = process_cpu_s();
        stopped = true;
        done_cv.notify_all();
        return;
      }
      if (echoed == 0) cpu_start = process_cpu_s();
      writer->write(const_cast<T*>(&ping));
      ++echoed;
    });
  });
  entities.reader("plumb/bench/ping", kLatencyDepth, &listener);
  {
    std::unique_lock lock(mutex);
    done_cv.wait_for(lock, seconds_of(seconds + 30), [&] { return stopped; });
  }
  listener.close();
  entities.silence();
  const double cpu_us = echoed > 0 && cpu_end > cpu_start ? (cpu_end - cpu_start) * 1e6 / static_cast<double>(echoed.load()) : 0;
  std::printf("RESULT echoed=%llu stopped=%d cpu_us=%.3f\n", static_cast<unsigned long long>(echoed.load()), stopped ? 1 : 0,
              cpu_us);
  std::fflush(stdout);  // before the teardown of the vendor entities
  return 0;
}

template <class T> int run_source(Entities& entities, double seconds) {
  T message;
  fill(message);
  dds::DataWriter* writer = entities.writer("plumb/bench/data", kThroughputDepth);
  if (!wait_until([&] { return writer_matched(*writer); })) {
    std::cerr << "source: the sink process was not discovered" << std::endl;
    return 1;
  }
  std::this_thread::sleep_for(200ms);  // the reader side matches a little after the writer side
  const double cpu_start = process_cpu_s();
  const auto start = Clock::now();
  const auto end = start + seconds_of(seconds + 0.5);
  std::uint64_t seq = 0;
  while (Clock::now() < end) {
    for (int i = 0; i < 64; ++i) {
      set_seq(message, seq++);
      writer->write(&message);
    }
  }
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  const double cpu_us = (process_cpu_s() - cpu_start) * 1e6 / static_cast<double>(seq);
  set_seq(message, kStopSeq);
  for (int i = 0; i < 5; ++i) {
    writer->write(&message);
    std::this_thread::sleep_for(50ms);
  }
  std::printf("RESULT sent=%llu seconds=%.6f cpu_us=%.3f\n", static_cast<unsigned long long>(seq), elapsed, cpu_us);
  std::fflush(stdout);  // before the teardown of the vendor entities
  return 0;
}

template <class T> int run_sink(Entities& entities, double seconds) {
  std::mutex mutex;
  std::condition_variable done_cv;
  bool done = false;
  const auto window = seconds_of(seconds);
  std::uint64_t received = 0, lowest = kStopSeq, highest = 0;
  Clock::time_point first;
  double cpu_start = 0, cpu_end = 0;  // over the window
  // Counts what arrives during the window from the first message, taking batches.
  Taker<T> taker;
  Listener listener([&](dds::DataReader& reader) {
    taker.take_all(reader, [&](const T& message) {
      const auto now = Clock::now();
      std::lock_guard lock(mutex);
      const std::uint64_t seq = get_seq(message);
      if (seq == kStopSeq || (received > 0 && now - first > window)) {
        if (cpu_end == 0) cpu_end = process_cpu_s();
        done = true;
        done_cv.notify_all();
        return;
      }
      if (received == 0) {
        first = now;
        cpu_start = process_cpu_s();
      }
      ++received;
      lowest = std::min(lowest, seq);
      highest = std::max(highest, seq);
    });
  });
  entities.reader("plumb/bench/data", kThroughputDepth, &listener);
  std::unique_lock lock(mutex);
  const bool complete = done_cv.wait_for(lock, window + 30s, [&] { return done; });
  lock.unlock();
  listener.close();
  entities.silence();
  if (!complete || received < 2) {
    std::cerr << "sink: received " << received << " messages, measurement " << (complete ? "complete" : "incomplete")
              << std::endl;
    return 1;
  }
  std::printf("RESULT received=%llu sent=%llu seconds=%.6f cpu_us=%.3f\n", static_cast<unsigned long long>(received),
              static_cast<unsigned long long>(highest - lowest + 1),
              std::min(seconds, std::chrono::duration<double>(Clock::now() - first).count()),
              (cpu_end - cpu_start) * 1e6 / static_cast<double>(received));
  std::fflush(stdout);  // before the teardown of the vendor entities
  return 0;
}

template <class T> int run_typed(const std::string& role, Entities& entities, double seconds) {
  if (role == "ping") return run_ping<T>(entities, seconds);
  if (role == "pong") return run_pong<T>(entities, seconds);
  if (role == "source") return run_source<T>(entities, seconds);
  if (role == "sink") return run_sink<T>(entities, seconds);
  std::cerr << "unknown role '" << role << "'" << std::endl;
  return 1;
}

}  // namespace

int run_role(const std::string& role, const std::string& type, int domain_id, double seconds) {
  const std::string name = "plumb-bench-native-fastdds-" + role;
  if (type == "sensor") {
    Entities entities(domain_id, new plumb::msg::SensorBatchPubSubType(), name.c_str());
    return run_typed<plumb::msg::SensorBatch>(role, entities, seconds);
  }
  if (type == "attitude") {
    Entities entities(domain_id, new plumb::msg::AttitudePubSubType(), name.c_str());
    return run_typed<plumb::msg::Attitude>(role, entities, seconds);
  }
  std::cerr << "unknown message type '" << type << "'" << std::endl;
  return 1;
}

}  // namespace native_fastdds
