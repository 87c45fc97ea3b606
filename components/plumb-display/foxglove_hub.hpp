// Between the DDS readers and the Foxglove clients: the channels advertised (one per plumb topic
// that has a writer), each client's subscriptions, and one bounded queue per client. The DDS side
// only appends to queues under short locks; each client's own sender thread empties its queue at
// the client's pace. A client that is slow or stalled loses the oldest messages of its queue,
// counted, and never slows the DDS side.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "foxglove_protocol.hpp"

namespace plumb::display_component {

using CdrBytes = std::shared_ptr<const std::vector<std::uint8_t>>;

struct FoxgloveOptions {
  std::size_t queue = 4096;  // messages queued per client (4 s of a 1 kHz topic) before the oldest go
  std::string server_name = "plumb-display";
};

// What a sender thread writes next: a JSON text or a binary frame.
struct FoxgloveFrame {
  bool binary = false;
  std::string text;
  std::vector<std::uint8_t> data;
};

class FoxgloveClient {
 public:
  // Waits until something is due and moves it to `out` (control messages first, then the queued
  // messages, oldest first, at most `max` of them as frames); false once closed.
  bool next(std::vector<FoxgloveFrame>& out, std::size_t max = 256);
  void close();
  std::uint64_t dropped() const;
  std::size_t queued() const;

 private:
  friend class FoxgloveHub;
  struct Pending {
    std::uint32_t subscription;
    std::uint64_t receive_ns;
    CdrBytes cdr;
  };
  explicit FoxgloveClient(std::size_t capacity) : capacity_(capacity) {}
  void control(std::string text);     // takes mutex_
  void push(const Pending& message);  // takes mutex_
  void forget(std::uint32_t subscription);  // drops what is queued for it (takes mutex_)

  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  std::deque<std::string> control_;
  std::deque<Pending> messages_;
  bool closed_ = false;
  std::uint64_t dropped_ = 0;
  // Under the hub's mutex: channel id -> subscription id, and the reverse.
  std::map<std::uint32_t, std::uint32_t> by_channel_;
  std::map<std::uint32_t, std::uint32_t> by_subscription_;
};

struct FoxgloveStats {
  std::size_t clients = 0;
  std::uint64_t clients_total = 0;
  std::size_t channels = 0;
  std::uint64_t messages = 0;  // messages queued for clients (one per subscribed client)
  std::uint64_t dropped = 0;   // dropped for slow clients, over all clients ever
};

class FoxgloveHub {
 public:
  explicit FoxgloveHub(FoxgloveOptions options = {});

  // DDS side. advertise() returns the channel's id: the same one again for a topic that comes back
  // with the same type (the protocol allows the reuse only then). Messages of a channel nobody
  // subscribed to are not asked for (wanted() says which are).
  // A channel the display makes itself (not a DDS topic) gives its own encodings ("json", "jsonschema").
  std::uint32_t advertise(const std::string& topic, const std::string& schema_name, const std::string& schema,
                          const std::string& encoding = "cdr", const std::string& schema_encoding = "omgidl");
  void unadvertise(const std::string& topic);
  void publish(std::uint32_t channel_id, std::uint64_t receive_ns, const CdrBytes& cdr);
  // Channels with at least one subscription: the DDS side reads only those topics.
  std::set<std::uint32_t> wanted() const;
  std::optional<foxglove::Channel> channel(std::uint32_t id) const;

  // Client side: join() queues serverInfo and the advertisement of every channel.
  std::shared_ptr<FoxgloveClient> join();
  void leave(const std::shared_ptr<FoxgloveClient>& client);
  // A text message of the client (subscribe, unsubscribe); what it cannot do is answered with a status.
  void receive(const std::shared_ptr<FoxgloveClient>& client, const std::string& text);

  FoxgloveStats stats() const;

 private:
  void unsubscribe(FoxgloveClient& client, std::uint32_t subscription);  // under mutex_

  const FoxgloveOptions options_;
  const std::string session_id_;
  mutable std::mutex mutex_;
  std::vector<std::shared_ptr<FoxgloveClient>> clients_;
  std::map<std::uint32_t, foxglove::Channel> channels_;  // advertised now, by id
  std::map<std::string, foxglove::Channel> known_;       // every topic ever advertised, for id reuse
  std::uint32_t next_channel_id_ = 1;
  FoxgloveStats stats_;
  std::uint64_t dropped_by_gone_ = 0;
};

}  // namespace plumb::display_component
