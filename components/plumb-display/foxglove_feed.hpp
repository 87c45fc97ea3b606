// The DDS side of plumb-display's Foxglove server: every plumb topic that discovery shows with a
// writer becomes a channel (its IDL text as the schema), and goes again when its last writer has
// gone. A topic is read only while some client subscribes to it: with no Foxglove client the
// display reads nothing more than its page needs. Each message taken is serialized to the CDR bytes
// a recording stores (encapsulation header included) and handed to the hub. Runs on a thread of
// its own, which never waits for a client.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "foxglove_hub.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::display_component {

class FoxgloveFeed {
 public:
  FoxgloveFeed(transport::Participant& participant, FoxgloveHub& hub);
  ~FoxgloveFeed();
  FoxgloveFeed(const FoxgloveFeed&) = delete;
  FoxgloveFeed& operator=(const FoxgloveFeed&) = delete;

  std::size_t readers() const { return readers_count_; }
  std::uint64_t messages() const { return messages_; }

  struct Stream;

 private:
  void run();
  void discover();
  void follow_subscriptions();
  void wake();

  transport::Participant& participant_;
  FoxgloveHub& hub_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool pending_ = false;
  bool stop_ = false;
  // Advertised topics: name -> (type, channel id).
  struct Topic {
    const transport::TypeSupport* type = nullptr;
    std::uint32_t channel = 0;
  };
  std::map<std::string, Topic> topics_;
  std::map<std::uint32_t, std::unique_ptr<Stream>> streams_;  // by channel id: the topics read now
  std::atomic<std::size_t> readers_count_{0};
  std::atomic<std::uint64_t> messages_{0};
  std::thread thread_;
};

}  // namespace plumb::display_component
