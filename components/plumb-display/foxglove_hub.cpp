#include "foxglove_hub.hpp"

#include <chrono>
#include <stdexcept>

namespace plumb::display_component {

using foxglove::StatusLevel;

bool FoxgloveClient::next(std::vector<FoxgloveFrame>& out, std::size_t max) {
  out.clear();
  std::deque<std::string> control;
  std::vector<Pending> messages;
  {
    std::unique_lock lock(mutex_);
    cv_.wait(lock, [this] { return closed_ || !control_.empty() || !messages_.empty(); });
    if (closed_) return false;
    control.swap(control_);
    while (!messages_.empty() && messages.size() < max) {
      messages.push_back(std::move(messages_.front()));
      messages_.pop_front();
    }
  }
  // The frames are built outside the lock: the DDS side never waits for this copy.
  for (auto& text : control) {
    FoxgloveFrame f;
    f.text = std::move(text);
    out.push_back(std::move(f));
  }
  for (const auto& m : messages) {
    FoxgloveFrame f;
    f.binary = true;
    foxglove::message_data_frame(m.subscription, m.receive_ns, m.cdr->data(), m.cdr->size(), f.data);
    out.push_back(std::move(f));
  }
  return true;
}

void FoxgloveClient::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  cv_.notify_all();
}

std::uint64_t FoxgloveClient::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

std::size_t FoxgloveClient::queued() const {
  std::lock_guard lock(mutex_);
  return messages_.size();
}

void FoxgloveClient::control(std::string text) {
  {
    std::lock_guard lock(mutex_);
    control_.push_back(std::move(text));
  }
  cv_.notify_one();
}

void FoxgloveClient::push(const Pending& message) {
  {
    std::lock_guard lock(mutex_);
    if (messages_.size() >= capacity_) {
      messages_.pop_front();
      ++dropped_;
    }
    messages_.push_back(message);
  }
  cv_.notify_one();
}

void FoxgloveClient::forget(std::uint32_t subscription) {
  std::lock_guard lock(mutex_);
  std::erase_if(messages_, [subscription](const Pending& m) { return m.subscription == subscription; });
}

namespace {
std::string new_session_id() {
  // Tells a reconnecting client whether it met the same server instance: its start time is enough.
  return std::to_string(
      std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch()).count());
}
}  // namespace

FoxgloveHub::FoxgloveHub(FoxgloveOptions options) : options_(std::move(options)), session_id_(new_session_id()) {
  if (options_.queue == 0) throw std::invalid_argument("the Foxglove queue must hold at least one message");
}

std::uint32_t FoxgloveHub::advertise(const std::string& topic, const std::string& schema_name, const std::string& schema,
                                     const std::string& encoding, const std::string& schema_encoding) {
  std::lock_guard lock(mutex_);
  auto known = known_.find(topic);
  if (known != known_.end() && (known->second.schema_name != schema_name || known->second.schema != schema)) {
    known_.erase(known);  // the same topic with another type: a new channel id
    known = known_.end();
  }
  if (known == known_.end()) {
    foxglove::Channel c;
    c.id = next_channel_id_++;
    c.topic = topic;
    c.schema_name = schema_name;
    c.schema = schema;
    c.encoding = encoding;
    c.schema_encoding = schema_encoding;
    known = known_.emplace(topic, std::move(c)).first;
  }
  const foxglove::Channel& c = known->second;
  if (channels_.emplace(c.id, c).second) {
    const std::string text = foxglove::advertise_json({c});
    for (auto& client : clients_) client->control(text);
  }
  stats_.channels = channels_.size();
  return c.id;
}

void FoxgloveHub::unadvertise(const std::string& topic) {
  std::lock_guard lock(mutex_);
  const auto known = known_.find(topic);
  if (known == known_.end() || !channels_.erase(known->second.id)) return;
  const std::uint32_t id = known->second.id;
  // Each client's subscription to it ends with it (the protocol says a client forgets them).
  for (auto& client : clients_) {
    if (const auto sub = client->by_channel_.find(id); sub != client->by_channel_.end()) unsubscribe(*client, sub->second);
    client->control(foxglove::unadvertise_json({id}));
  }
  stats_.channels = channels_.size();
}

void FoxgloveHub::publish(std::uint32_t channel_id, std::uint64_t receive_ns, const CdrBytes& cdr) {
  std::lock_guard lock(mutex_);
  for (auto& client : clients_) {
    const auto sub = client->by_channel_.find(channel_id);
    if (sub == client->by_channel_.end()) continue;
    client->push({sub->second, receive_ns, cdr});
    ++stats_.messages;
  }
}

std::set<std::uint32_t> FoxgloveHub::wanted() const {
  std::lock_guard lock(mutex_);
  std::set<std::uint32_t> ids;
  for (const auto& client : clients_) {
    for (const auto& [channel, sub] : client->by_channel_) ids.insert(channel);
  }
  return ids;
}

std::optional<foxglove::Channel> FoxgloveHub::channel(std::uint32_t id) const {
  std::lock_guard lock(mutex_);
  const auto c = channels_.find(id);
  if (c == channels_.end()) return std::nullopt;
  return c->second;
}

std::shared_ptr<FoxgloveClient> FoxgloveHub::join() {
  auto client = std::shared_ptr<FoxgloveClient>(new FoxgloveClient(options_.queue));
  std::lock_guard lock(mutex_);
  client->control(foxglove::server_info_json(options_.server_name, session_id_));
  // The protocol wants at least one advertise on connection, even with no channel yet.
  std::vector<foxglove::Channel> all;
  for (const auto& [id, c] : channels_) all.push_back(c);
  client->control(foxglove::advertise_json(all));
  clients_.push_back(client);
  ++stats_.clients_total;
  stats_.clients = clients_.size();
  return client;
}

void FoxgloveHub::leave(const std::shared_ptr<FoxgloveClient>& client) {
  client->close();
  std::lock_guard lock(mutex_);
  std::erase(clients_, client);
  dropped_by_gone_ += client->dropped();
  stats_.clients = clients_.size();
}

void FoxgloveHub::unsubscribe(FoxgloveClient& client, std::uint32_t subscription) {
  const auto s = client.by_subscription_.find(subscription);
  if (s == client.by_subscription_.end()) return;
  client.by_channel_.erase(s->second);
  client.by_subscription_.erase(s);
  client.forget(subscription);  // nothing of it is sent after the client said it is done with it
}

void FoxgloveHub::receive(const std::shared_ptr<FoxgloveClient>& client, const std::string& text) {
  const foxglove::ClientMessage message = foxglove::parse_client_message(text);
  std::lock_guard lock(mutex_);
  if (const auto* s = std::get_if<foxglove::Subscribe>(&message)) {
    for (const auto& sub : s->subscriptions) {
      if (!channels_.count(sub.channel_id)) {
        client->control(foxglove::status_json(StatusLevel::Warning, "no channel " + std::to_string(sub.channel_id) +
                                                                        " (unadvertised or never advertised)"));
      } else if (client->by_subscription_.count(sub.id)) {
        client->control(foxglove::status_json(StatusLevel::Error, "subscription id " + std::to_string(sub.id) + " is in use"));
      } else if (client->by_channel_.count(sub.channel_id)) {
        client->control(foxglove::status_json(StatusLevel::Warning, "channel " + std::to_string(sub.channel_id) +
                                                                        " is already subscribed (one subscription per channel)"));
      } else {
        client->by_channel_[sub.channel_id] = sub.id;
        client->by_subscription_[sub.id] = sub.channel_id;
      }
    }
  } else if (const auto* u = std::get_if<foxglove::Unsubscribe>(&message)) {
    for (const std::uint32_t id : u->subscription_ids) unsubscribe(*client, id);
  } else if (const auto* x = std::get_if<foxglove::Unsupported>(&message)) {
    client->control(foxglove::status_json(StatusLevel::Warning, "plumb-display does not offer '" + x->op + "' (it serves subscriptions only)"));
  } else if (const auto* bad = std::get_if<foxglove::Invalid>(&message)) {
    client->control(foxglove::status_json(StatusLevel::Error, "message not understood: " + bad->why));
  }
}

FoxgloveStats FoxgloveHub::stats() const {
  std::lock_guard lock(mutex_);
  FoxgloveStats s = stats_;
  s.dropped = dropped_by_gone_;
  for (const auto& c : clients_) s.dropped += c->dropped();
  return s;
}

}  // namespace plumb::display_component
