#include "foxglove_feed.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "plumb/topics/cdr.hpp"
#include "plumb/transport/with_topic_type.hpp"

namespace plumb::display_component {

struct FoxgloveFeed::Stream {
  virtual ~Stream() = default;
  // Hands everything taken to the hub; returns how many messages.
  virtual std::size_t drain(FoxgloveHub& hub) = 0;
};

namespace {

constexpr std::size_t kFoxgloveTakeBatch = 256;
// A reader keeps this many messages for the feed's thread: a 1 kHz topic's quarter second, so a
// thread held up a moment (a busy machine) loses nothing of a best-effort stream.
constexpr std::int32_t kFoxgloveReaderDepth = 256;

std::uint64_t foxglove_now_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch()).count());
}

template <class M> class FoxgloveStream final : public FoxgloveFeed::Stream {
 public:
  FoxgloveStream(transport::Reader<M> reader, std::uint32_t channel) : reader_(std::move(reader)), channel_(channel) {}

  std::size_t drain(FoxgloveHub& hub) override {
    std::size_t n = 0;
    while (reader_.take(taken_, kFoxgloveTakeBatch) > 0) {
      const std::uint64_t rx = foxglove_now_ns();  // one take: every message of it arrived by now
      for (const M& m : taken_) {
        // One buffer per message, shared by every client's queue: the bytes a recording stores.
        auto bytes = std::make_shared<std::vector<std::uint8_t>>();
        topics::cdr::serialize(m, *bytes);
        hub.publish(channel_, rx, std::move(bytes));
      }
      n += taken_.size();
    }
    return n;
  }

 private:
  transport::Reader<M> reader_;
  std::uint32_t channel_;
  std::vector<M> taken_;
};

}  // namespace

FoxgloveFeed::FoxgloveFeed(transport::Participant& participant, FoxgloveHub& hub)
    : participant_(participant), hub_(hub), thread_([this] { run(); }) {}

FoxgloveFeed::~FoxgloveFeed() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  cv_.notify_all();
  thread_.join();
  streams_.clear();  // the readers go before anything their callbacks touch
}

void FoxgloveFeed::wake() {
  {
    std::lock_guard lock(mutex_);
    pending_ = true;
  }
  cv_.notify_one();
}

void FoxgloveFeed::discover() {
  std::map<std::string, const transport::TypeSupport*> alive;
  for (const auto& t : participant_.discovered_topics()) {
    if (t.writers == 0) continue;
    if (const auto* type = topics::find_type_support(t.type_name)) alive.emplace(t.name, type);
  }
  for (auto it = topics_.begin(); it != topics_.end();) {
    const auto now = alive.find(it->first);
    if (now != alive.end() && *now->second == *it->second.type) {
      ++it;
      continue;
    }
    // Its last writer is gone (or it changed type): no more channel, no more reader.
    streams_.erase(it->second.channel);
    hub_.unadvertise(it->first);
    it = topics_.erase(it);
  }
  for (const auto& [name, type] : alive) {
    if (topics_.count(name)) continue;
    const std::string schema =
        transport::with_topic_type(*type, [](auto proto) { return std::string(topics::idl_source<decltype(proto)>()); });
    topics_[name] = {type, hub_.advertise(name, type->type_name, schema)};
  }
}

void FoxgloveFeed::follow_subscriptions() {
  const std::set<std::uint32_t> wanted = hub_.wanted();
  std::erase_if(streams_, [&](const auto& s) { return !wanted.count(s.first); });
  for (const auto& entry : topics_) {
    const std::string& name = entry.first;  // not a structured binding: the lambda below captures it
    const Topic& topic = entry.second;
    if (!wanted.count(topic.channel) || streams_.count(topic.channel)) continue;
    auto qos = transport::default_qos_for_topic(name);
    if (qos.history == transport::History::KeepLast) qos.depth = std::max(qos.depth, kFoxgloveReaderDepth);
    const std::uint32_t channel = topic.channel;
    streams_[channel] = transport::with_topic_type(*topic.type, [&](auto proto) -> std::unique_ptr<Stream> {
      using M = decltype(proto);
      return std::make_unique<FoxgloveStream<M>>(transport::make_reader<M>(participant_, name, qos, [this] { wake(); }),
                                                 channel);
    });
  }
  readers_count_ = streams_.size();
}

void FoxgloveFeed::run() {
  auto last_discovery = std::chrono::steady_clock::time_point{};
  for (;;) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_discovery >= std::chrono::milliseconds(500)) {
      last_discovery = now;
      discover();
    }
    // A subscription is followed within one wait (50 ms), the readers' data as it comes.
    follow_subscriptions();
    {
      std::unique_lock lock(mutex_);
      cv_.wait_for(lock, std::chrono::milliseconds(50), [this] { return pending_ || stop_; });
      if (stop_) return;
      pending_ = false;
    }
    std::size_t n = 0;
    for (auto& [channel, stream] : streams_) n += stream->drain(hub_);
    messages_ += n;
  }
}

}  // namespace plumb::display_component
