#include "foxglove_protocol.hpp"

#include <limits>

#include "json.hpp"

namespace plumb::display_component::foxglove {
namespace {

Json channel_json(const Channel& c) {
  Json j;
  j["id"] = c.id;
  j["topic"] = c.topic;
  j["encoding"] = c.encoding;
  j["schemaName"] = c.schema_name;
  j["schema"] = c.schema;
  j["schemaEncoding"] = c.schema_encoding;
  return j;
}

void append_le(std::vector<std::uint8_t>& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

// An id of the protocol: a JSON integer in [0, 2^32).
bool read_id(const Json& j, const char* field, std::uint32_t& out) {
  if (!j.is_object() || !j.contains(field)) return false;
  const Json& v = j[field];
  if (!v.is_number_integer() || v.get<std::int64_t>() < 0 ||
      v.get<std::int64_t>() > static_cast<std::int64_t>(std::numeric_limits<std::uint32_t>::max())) {
    return false;
  }
  out = static_cast<std::uint32_t>(v.get<std::int64_t>());
  return true;
}

}  // namespace

std::string server_info_json(const std::string& name, const std::string& session_id) {
  Json j;
  j["op"] = "serverInfo";
  j["name"] = name;
  // Subscribing is not a capability: every server offers it. Nothing optional is offered (no client
  // publishing, parameters, services), so supportedEncodings, which only those use, is left out.
  j["capabilities"] = Json::array();
  j["metadata"] = Json::object();
  j["sessionId"] = session_id;
  return json_text(j);
}

std::string advertise_json(const std::vector<Channel>& channels) {
  Json j;
  j["op"] = "advertise";
  j["channels"] = Json::array();
  for (const auto& c : channels) j["channels"].push_back(channel_json(c));
  return json_text(j);
}

std::string unadvertise_json(const std::vector<std::uint32_t>& channel_ids) {
  Json j;
  j["op"] = "unadvertise";
  j["channelIds"] = channel_ids;
  return json_text(j);
}

std::string status_json(StatusLevel level, const std::string& message) {
  Json j;
  j["op"] = "status";
  j["level"] = static_cast<int>(level);
  j["message"] = message;
  return json_text(j);
}

void message_data_frame(std::uint32_t subscription_id, std::uint64_t receive_time_ns, const std::uint8_t* payload,
                        std::size_t size, std::vector<std::uint8_t>& out) {
  out.clear();
  out.reserve(kMessageDataHeader + size);
  out.push_back(static_cast<std::uint8_t>(BinaryOpcode::MessageData));
  append_le(out, subscription_id, 4);
  append_le(out, receive_time_ns, 8);
  out.insert(out.end(), payload, payload + size);
}

ClientMessage parse_client_message(const std::string& text) {
  const Json j = Json::parse(text, nullptr, false);
  if (j.is_discarded()) return Invalid{"not JSON"};
  if (!j.is_object() || !j.contains("op") || !j["op"].is_string()) return Invalid{"no \"op\" string"};
  const std::string op = j["op"].get<std::string>();
  if (op == "subscribe") {
    if (!j.contains("subscriptions") || !j["subscriptions"].is_array()) return Invalid{"subscribe without a \"subscriptions\" array"};
    Subscribe s;
    for (const Json& e : j["subscriptions"]) {
      Subscription sub;
      if (!read_id(e, "id", sub.id) || !read_id(e, "channelId", sub.channel_id)) {
        return Invalid{"subscribe: each subscription needs integer \"id\" and \"channelId\""};
      }
      s.subscriptions.push_back(sub);
    }
    return s;
  }
  if (op == "unsubscribe") {
    if (!j.contains("subscriptionIds") || !j["subscriptionIds"].is_array()) return Invalid{"unsubscribe without a \"subscriptionIds\" array"};
    Unsubscribe u;
    for (const Json& e : j["subscriptionIds"]) {
      if (!e.is_number_integer() || e.get<std::int64_t>() < 0 ||
          e.get<std::int64_t>() > static_cast<std::int64_t>(std::numeric_limits<std::uint32_t>::max())) {
        return Invalid{"unsubscribe: subscription ids are integers"};
      }
      u.subscription_ids.push_back(static_cast<std::uint32_t>(e.get<std::int64_t>()));
    }
    return u;
  }
  return Unsupported{op};
}

}  // namespace plumb::display_component::foxglove
