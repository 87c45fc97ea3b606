#include "roles.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <ctime>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <thread>
#include <vector>

#include "payloads.hpp"
#include "plumb/transport/loader.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::bench {
namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;
namespace tr = plumb::transport;

constexpr auto kMatchTimeout = 15s;
constexpr std::size_t kWarmupRoundTrips = 200;
// Messages per batched take, as many as the native programs take per call.
constexpr std::size_t kTakeBatch = 64;

// Reliable and keep-last, like ddsperf's ping/pong (which is keep-last 1; one message is in flight).
tr::Qos latency_qos() { return tr::Qos::attitude(); }
// The sensor stream profile for runs where nothing may be lost.
tr::Qos throughput_qos() { return tr::Qos::reliable_stream(); }

// The reader as seen from its own on_data callback, which may fire before make_reader() returns and
// must be finished before the reader is destroyed: the callback runs under the gate's lock and does
// nothing while the gate is closed. An exception in a callback is reported instead of escaping into
// the vendor's thread.
template <class T> class ReaderGate {
 public:
  void open(tr::Reader<T>& reader) {
    std::lock_guard lock(mutex_);
    reader_ = &reader;
  }
  void close() {
    std::lock_guard lock(mutex_);
    reader_ = nullptr;
  }
  template <class F> void with_reader(F&& use) {
    std::lock_guard lock(mutex_);
    if (reader_ == nullptr) return;
    try {
      use(*reader_);
    } catch (const std::exception& e) {
      std::cerr << "data callback: " << e.what() << std::endl;
      reader_ = nullptr;
      failed_ = true;
    }
  }
  bool failed() {
    std::lock_guard lock(mutex_);
    return failed_;
  }

 private:
  std::mutex mutex_;
  tr::Reader<T>* reader_ = nullptr;
  bool failed_ = false;
};

// Completion flag for the main thread, set from vendor threads.
class Done {
 public:
  void set() {
    std::lock_guard lock(mutex_);
    done_ = true;
    cv_.notify_all();
  }
  bool wait_for(Clock::duration timeout) {
    std::unique_lock lock(mutex_);
    return cv_.wait_for(lock, timeout, [&] { return done_; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  bool done_ = false;
};

template <class Endpoint> bool wait_until(Endpoint&& ready, Clock::duration timeout) {
  const auto deadline = Clock::now() + timeout;
  while (!ready()) {
    if (Clock::now() > deadline) return false;
    std::this_thread::sleep_for(10ms);
  }
  return true;
}

// CPU time of this whole process (every thread: ours and the vendor's), in seconds. Per message,
// it tells what plumb costs beside the native programs even when a busy machine makes the
// wall-clock figures noisy.
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

// Ping: the next ping leaves from the pong's data callback, as in ddsperf's listener mode, so the
// round trip contains no thread hand-over in this process.
template <class T> int run_ping(tr::Participant& participant, double seconds) {
  T message = make_payload<T>();
  auto writer = tr::make_writer<T>(participant, kPingTopic, latency_qos());
  ReaderGate<T> gate;
  Done done;
  std::mutex mutex;  // guards the fields below, touched by the callback and the watchdog
  std::vector<double> one_way_us;
  std::uint64_t seq = 0;
  Clock::time_point sent_at;
  Clock::time_point measure_until = Clock::time_point::max();
  bool finished = false;
  double cpu_start = 0, cpu_end = 0;  // over the measured round trips

  std::vector<T> pongs;  // used by the data callback only
  auto on_pong = [&] { gate.with_reader([&](tr::Reader<T>& reader) {
    do {
      reader.take(pongs, kTakeBatch);
      for (const T& pong : pongs) {
        const auto now = Clock::now();
        std::lock_guard lock(mutex);
        if (finished || get_seq(pong) != seq) continue;
        if (seq >= kWarmupRoundTrips) {
          one_way_us.push_back(std::chrono::duration<double, std::micro>(now - sent_at).count() / 2);
        } else if (seq + 1 == kWarmupRoundTrips) {
          measure_until = now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
          cpu_start = process_cpu_s();
        }
        if (now >= measure_until) {
          cpu_end = process_cpu_s();
          finished = true;
          done.set();
          continue;
        }
        set_seq(message, ++seq);
        sent_at = Clock::now();
        writer.write(message);
      }
    } while (pongs.size() == kTakeBatch);
  }); };
  auto reader = tr::make_reader<T>(participant, kPongTopic, latency_qos(), on_pong);
  gate.open(reader);

  if (!wait_until([&] { return writer.matched_readers() > 0 && reader.matched_writers() > 0; }, kMatchTimeout)) {
    std::cerr << "ping: the pong process was not discovered within " << kMatchTimeout.count() << " s" << std::endl;
    return 1;
  }
  {
    std::lock_guard lock(mutex);
    set_seq(message, seq);
    sent_at = Clock::now();
    writer.write(message);
  }
  // Watchdog: a ping sent before the pong's reader had matched our writer may only be repaired
  // by a later heartbeat; resend the current one when nothing moved for a while.
  const auto give_up = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds + 20));
  std::uint64_t last_seq = 0;
  while (!done.wait_for(500ms)) {
    std::lock_guard lock(mutex);
    if (Clock::now() > give_up) {
      finished = true;
      std::cerr << "ping: stalled after " << seq << " round trips" << std::endl;
      break;
    }
    if (seq == last_seq) {
      sent_at = Clock::now();
      writer.write(message);
    }
    last_seq = seq;
  }
  gate.close();
  {
    std::lock_guard lock(mutex);
    T stop = make_payload<T>();
    set_seq(stop, kStopSeq);
    writer.write(stop);
  }
  std::this_thread::sleep_for(100ms);  // let the stop message go out before the writer is deleted
  std::lock_guard lock(mutex);
  if (one_way_us.empty() || gate.failed()) return 1;
  std::printf("RESULT count=%zu median_us=%.3f p99_us=%.3f cpu_us=%.3f\n", one_way_us.size(), percentile(one_way_us, 0.5),
              percentile(one_way_us, 0.99), (cpu_end - cpu_start) * 1e6 / static_cast<double>(one_way_us.size()));
  return 0;
}

// Pong: echoes every ping from the data callback until the stop message or the time limit.
template <class T> int run_pong(tr::Participant& participant, double seconds) {
  auto writer = tr::make_writer<T>(participant, kPongTopic, latency_qos());
  ReaderGate<T> gate;
  Done done;
  std::atomic<std::uint64_t> echoed{0};
  double cpu_start = 0, cpu_end = 0;  // from the first echo to the stop message (data callback only)
  std::vector<T> pings;  // used by the data callback only
  auto on_ping = [&] { gate.with_reader([&](tr::Reader<T>& reader) {
    do {
      reader.take(pings, kTakeBatch);
      for (const T& ping : pings) {
        if (get_seq(ping) == kStopSeq) {
          cpu_end = process_cpu_s();
          done.set();
          continue;
        }
        if (echoed == 0) cpu_start = process_cpu_s();
        writer.write(ping);
        ++echoed;
      }
    } while (pings.size() == kTakeBatch);
  }); };
  auto reader = tr::make_reader<T>(participant, kPingTopic, latency_qos(), on_ping);
  gate.open(reader);
  const bool stopped = done.wait_for(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds + 30)));
  gate.close();
  const double cpu_us = echoed > 0 && cpu_end > cpu_start ? (cpu_end - cpu_start) * 1e6 / static_cast<double>(echoed.load()) : 0;
  std::printf("RESULT echoed=%llu stopped=%d cpu_us=%.3f\n", static_cast<unsigned long long>(echoed.load()), stopped ? 1 : 0,
              cpu_us);
  return gate.failed() ? 1 : 0;
}

// Source: writes as fast as write() returns for `seconds` plus a margin that covers the sink's
// measuring window, then the stop message.
template <class T> int run_source(tr::Participant& participant, double seconds) {
  T message = make_payload<T>();
  auto writer = tr::make_writer<T>(participant, kDataTopic, throughput_qos());
  if (!wait_until([&] { return writer.matched_readers() > 0; }, kMatchTimeout)) {
    std::cerr << "source: the sink process was not discovered within " << kMatchTimeout.count() << " s" << std::endl;
    return 1;
  }
  std::this_thread::sleep_for(200ms);  // the reader side matches a little after the writer side
  const double cpu_start = process_cpu_s();
  const auto start = Clock::now();
  const auto end = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds + 0.5));
  std::uint64_t seq = 0;
  while (Clock::now() < end) {
    for (int i = 0; i < 64; ++i) {
      set_seq(message, seq++);
      writer.write(message);
    }
  }
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  const double cpu_us = (process_cpu_s() - cpu_start) * 1e6 / static_cast<double>(seq);
  set_seq(message, kStopSeq);
  for (int i = 0; i < 5; ++i) {
    writer.write(message);
    std::this_thread::sleep_for(50ms);
  }
  std::printf("RESULT sent=%llu seconds=%.6f cpu_us=%.3f\n", static_cast<unsigned long long>(seq), elapsed, cpu_us);
  return 0;
}

// Sink: counts what arrives during `seconds` from the first message (the source writes a little
// longer), and the sequence numbers it missed in that window.
template <class T> int run_sink(tr::Participant& participant, double seconds) {
  ReaderGate<T> gate;
  Done done;
  std::mutex mutex;
  const auto window = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  std::uint64_t received = 0, lowest = kStopSeq, highest = 0;
  Clock::time_point first;
  double cpu_start = 0, cpu_end = 0;  // over the window
  std::vector<T> messages;  // used by the data callback only
  auto on_data = [&] { gate.with_reader([&](tr::Reader<T>& reader) {
    do {
      reader.take(messages, kTakeBatch);
      const auto now = Clock::now();
      std::lock_guard lock(mutex);
      for (const T& message : messages) {
        const std::uint64_t seq = get_seq(message);
        if (seq == kStopSeq || (received > 0 && now - first > window)) {
          if (cpu_end == 0) cpu_end = process_cpu_s();
          done.set();
          continue;
        }
        if (received == 0) {
          first = now;
          cpu_start = process_cpu_s();
        }
        ++received;
        lowest = std::min(lowest, seq);
        highest = std::max(highest, seq);
      }
    } while (messages.size() == kTakeBatch);  // a short batch: the reader is empty
  }); };
  auto reader = tr::make_reader<T>(participant, kDataTopic, throughput_qos(), on_data);
  gate.open(reader);
  const bool complete = done.wait_for(window + 30s);
  gate.close();
  std::lock_guard lock(mutex);
  if (!complete || received < 2 || gate.failed()) {
    std::cerr << "sink: received " << received << " messages, measurement " << (complete ? "complete" : "incomplete")
              << std::endl;
    return 1;
  }
  // A stop message before the window ended means the source stopped early: rate over what we saw.
  std::printf("RESULT received=%llu sent=%llu seconds=%.6f cpu_us=%.3f\n", static_cast<unsigned long long>(received),
              static_cast<unsigned long long>(highest - lowest + 1),
              std::min(seconds, std::chrono::duration<double>(Clock::now() - first).count()),
              (cpu_end - cpu_start) * 1e6 / static_cast<double>(received));
  return 0;
}

template <class T> int run_typed(const RoleOptions& options, tr::Participant& participant) {
  if (options.role == "ping") return run_ping<T>(participant, options.seconds);
  if (options.role == "pong") return run_pong<T>(participant, options.seconds);
  if (options.role == "source") return run_source<T>(participant, options.seconds);
  if (options.role == "sink") return run_sink<T>(participant, options.seconds);
  std::cerr << "unknown role '" << options.role << "'" << std::endl;
  return 1;
}

}  // namespace

int run_role(const RoleOptions& options) {
  auto transport = tr::load_transport(options.transport);
  tr::ParticipantOptions participant_options;
  participant_options.domain_id = options.domain_id;
  participant_options.name = "plumb-bench-transport-" + options.role;
  auto participant = transport->create_participant(participant_options);
  if (options.type == "sensor") return run_typed<topics::SensorBatch>(options, *participant);
  if (options.type == "attitude") return run_typed<topics::Attitude>(options, *participant);
  std::cerr << "unknown message type '" << options.type << "'" << std::endl;
  return 1;
}

}  // namespace plumb::bench
