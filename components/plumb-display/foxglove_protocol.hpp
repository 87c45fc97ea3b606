// The Foxglove WebSocket protocol (subprotocol foxglove.websocket.v1), the part plumb-display
// speaks: the server's JSON messages (serverInfo, advertise, unadvertise, status), the binary
// message-data frame, and the client's subscribe and unsubscribe. Pure functions: no socket, no DDS.
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace plumb::display_component::foxglove {

inline constexpr const char* kSubprotocol = "foxglove.websocket.v1";

// The binary messages' opcodes, server to client.
enum class BinaryOpcode : std::uint8_t { MessageData = 1 };

// One channel, as advertised: a plumb topic with its CDR encoding and its IDL schema.
struct Channel {
  std::uint32_t id = 0;
  std::string topic;
  std::string encoding = "cdr";
  std::string schema_name;  // the scoped IDL name, "plumb::msg::Attitude"
  std::string schema;       // the IDL text (topics::idl_source<T>())
  std::string schema_encoding = "omgidl";
};

enum class StatusLevel { Info = 0, Warning = 1, Error = 2 };

std::string server_info_json(const std::string& name, const std::string& session_id);
std::string advertise_json(const std::vector<Channel>& channels);
std::string unadvertise_json(const std::vector<std::uint32_t>& channel_ids);
std::string status_json(StatusLevel level, const std::string& message);

// Opcode 1, the subscription id (u32), the receive time (u64, ns since the epoch), then the
// message's bytes as they are: all little-endian, 13 bytes before the payload.
inline constexpr std::size_t kMessageDataHeader = 13;
void message_data_frame(std::uint32_t subscription_id, std::uint64_t receive_time_ns, const std::uint8_t* payload,
                        std::size_t size, std::vector<std::uint8_t>& out);

// What a client sends.
struct Subscription {
  std::uint32_t id = 0;
  std::uint32_t channel_id = 0;
};
struct Subscribe {
  std::vector<Subscription> subscriptions;
};
struct Unsubscribe {
  std::vector<std::uint32_t> subscription_ids;
};
// A valid message of an operation plumb-display does not offer (client publish, parameters, ...).
struct Unsupported {
  std::string op;
};
// Not JSON, no "op", or fields of the wrong type: `why` says which.
struct Invalid {
  std::string why;
};
using ClientMessage = std::variant<Subscribe, Unsubscribe, Unsupported, Invalid>;

ClientMessage parse_client_message(const std::string& text);

}  // namespace plumb::display_component::foxglove
