// plumb record's machinery: one DDS reader per topic, each message written to the MCAP file as
// the CDR of its plumb::topics type, with log_time = when it was taken (ns since the epoch) and
// publish_time = the source's stamp (sample time of a sensor batch, window end of an estimate;
// the log time for types without one).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "plumb/mcap/writer.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::cli {

// Wakes the recording loop when any reader has data (the readers' on_data callbacks).
class DataSignal {
 public:
  void notify();
  // Waits until notified or `timeout`; clears the signal.
  void wait(std::chrono::milliseconds timeout);

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  bool pending_ = false;
};

class Recorder {
 public:
  // `reliable`: sensor topics are read reliable keep-all (lossless against reliable writers, as
  // plumb-sim --reliable and plumb-bridge --reliable publish) instead of their best-effort default.
  Recorder(transport::Participant& participant, mcap::Writer& writer, bool reliable);
  ~Recorder();

  // Subscribes to `topic` carrying `type` (once; a second call is ignored).
  void add(const std::string& topic, const transport::TypeSupport& type);
  bool has(const std::string& topic) const;
  // Writes everything the readers hold; returns how many messages. mcap::Error from the writer
  // (disk full) goes to the caller.
  std::size_t drain();
  void wait(std::chrono::milliseconds timeout) { signal_.wait(timeout); }

  struct TopicCount {
    std::string topic;
    std::uint64_t messages;
  };
  std::vector<TopicCount> counts() const;
  std::uint64_t messages() const;

  struct Subscription;

 private:
  transport::Participant& participant_;
  mcap::Writer& writer_;
  bool reliable_;
  DataSignal signal_;
  std::map<std::string, std::uint16_t> schemas_;  // type name -> schema id
  std::vector<std::unique_ptr<Subscription>> subscriptions_;
  std::set<std::string> topics_;
  std::vector<std::uint8_t> buffer_;  // CDR of one message, reused
};

}  // namespace plumb::cli
