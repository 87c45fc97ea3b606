#include "recording/recorder.hpp"

#include "messages/topic_type.hpp"
#include "plumb/topics/cdr.hpp"
#include "plumb/transport/topic_names.hpp"
#include "recording/recording.hpp"

namespace plumb::cli {

void DataSignal::notify() {
  {
    std::lock_guard lock(mutex_);
    pending_ = true;
  }
  cv_.notify_one();
}

void DataSignal::wait(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  cv_.wait_for(lock, timeout, [this] { return pending_; });
  pending_ = false;
}

namespace {

// Messages per batched take.
constexpr std::size_t kTakeBatch = 256;

std::uint64_t now_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch()).count());
}

// The source's own time of a message, when its type has one.
template <class M> std::uint64_t source_stamp(const M& m, std::uint64_t log_time) {
  std::int64_t stamp = -1;
  if constexpr (std::is_same_v<M, topics::SensorBatch>) {
    if (!m.samples.empty()) stamp = m.samples.front().stamp_ns;
  } else if constexpr (std::is_same_v<M, topics::Attitude>) {
    stamp = m.window_end_ns;
  } else if constexpr (std::is_same_v<M, topics::Truth>) {
    stamp = m.stamp_ns;
  }
  return stamp >= 0 ? static_cast<std::uint64_t>(stamp) : log_time;
}

std::string describe(const transport::Qos& q) {
  return std::string(q.reliability == transport::Reliability::Reliable ? "reliable" : "best_effort") + " " +
         (q.durability == transport::Durability::TransientLocal ? "transient_local" : "volatile") + " " +
         (q.history == transport::History::KeepAll ? "keep_all" : "keep_last " + std::to_string(q.depth));
}

}  // namespace

struct Recorder::Subscription {
  virtual ~Subscription() = default;
  virtual std::size_t drain(mcap::Writer& writer, std::vector<std::uint8_t>& buffer) = 0;
  std::string topic;
  std::uint16_t channel = 0;
  std::uint64_t messages = 0;
};

namespace {
template <class M> class TypedSubscription final : public Recorder::Subscription {
 public:
  explicit TypedSubscription(transport::Reader<M> reader) : reader_(std::move(reader)) {}

  std::size_t drain(mcap::Writer& writer, std::vector<std::uint8_t>& buffer) override {
    std::size_t n = 0;
    while (reader_.take(taken_, kTakeBatch) > 0) {
      const std::uint64_t log_time = now_ns();  // one take: every message of it arrived by now
      for (const M& m : taken_) {
        topics::cdr::serialize(m, buffer);
        mcap::MessageView view;
        view.channel_id = channel;
        view.sequence = static_cast<std::uint32_t>(messages);
        view.log_time = log_time;
        view.publish_time = source_stamp(m, log_time);
        view.data = buffer.data();
        view.size = buffer.size();
        writer.write(view);
        ++messages;
        ++n;
      }
    }
    return n;
  }

 private:
  transport::Reader<M> reader_;
  std::vector<M> taken_;
};
}  // namespace

Recorder::Recorder(transport::Participant& participant, mcap::Writer& writer, bool reliable)
    : participant_(participant), writer_(writer), reliable_(reliable) {}

Recorder::~Recorder() = default;

bool Recorder::has(const std::string& topic) const { return topics_.count(topic) > 0; }

void Recorder::add(const std::string& topic, const transport::TypeSupport& type) {
  if (has(topic)) return;
  auto qos = transport::default_qos_for_topic(topic);
  const bool sensor = type == topics::type_support<topics::SensorBatch>();
  if (sensor && reliable_) qos = {transport::Reliability::Reliable, transport::Durability::Volatile, transport::History::KeepAll, 0};
  auto schema = schemas_.find(type.type_name);
  if (schema == schemas_.end()) {
    const std::string text = with_topic_type(type, [](auto proto) { return std::string(topics::idl_source<decltype(proto)>()); });
    schema = schemas_.emplace(type.type_name, writer_.add_schema(type.type_name, kSchemaEncoding, text)).first;
  }
  std::unique_ptr<Subscription> sub = with_topic_type(type, [&](auto proto) -> std::unique_ptr<Subscription> {
    using M = decltype(proto);
    return std::make_unique<TypedSubscription<M>>(
        transport::make_reader<M>(participant_, topic, qos, [this] { signal_.notify(); }));
  });
  sub->topic = topic;
  sub->channel = writer_.add_channel(schema->second, topic, kMessageEncoding, {{"qos", describe(qos)}});
  subscriptions_.push_back(std::move(sub));
  topics_.insert(topic);
}

std::size_t Recorder::drain() {
  std::size_t n = 0;
  for (auto& s : subscriptions_) n += s->drain(writer_, buffer_);
  return n;
}

std::vector<Recorder::TopicCount> Recorder::counts() const {
  std::vector<TopicCount> out;
  for (const auto& s : subscriptions_) out.push_back({s->topic, s->messages});
  return out;
}

std::uint64_t Recorder::messages() const {
  std::uint64_t n = 0;
  for (const auto& s : subscriptions_) n += s->messages;
  return n;
}

}  // namespace plumb::cli
