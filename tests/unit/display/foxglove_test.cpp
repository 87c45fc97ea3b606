// plumb-display's Foxglove WebSocket protocol: the binary message frame byte by byte (opcode, ids,
// little-endian), the server's JSON messages as the spec names their fields, the client's messages
// parsed or refused, and the hub: what a client is sent on joining, subscriptions, a slow client's
// bounded queue (oldest dropped, counted), channels that go and their ids that come back.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "foxglove_hub.hpp"
#include "foxglove_protocol.hpp"

namespace plumb::display_component {
namespace {

namespace fg = foxglove;

nlohmann::json fox_parse(const FoxgloveFrame& f) {
  EXPECT_FALSE(f.binary);
  return nlohmann::json::parse(f.text);
}

// Everything the client has been sent so far (something must be due: next() waits otherwise).
std::vector<FoxgloveFrame> fox_take(FoxgloveClient& client) {
  std::vector<FoxgloveFrame> frames;
  EXPECT_TRUE(client.next(frames, 100000));
  return frames;
}

CdrBytes fox_bytes(std::initializer_list<std::uint8_t> b) { return std::make_shared<const std::vector<std::uint8_t>>(b); }

TEST(Foxglove, MessageDataFrameIsOpcodeSubscriptionTimeThenPayloadLittleEndian) {
  const std::uint8_t payload[] = {0x00, 0x01, 0x00, 0x00, 0xAA, 0xBB};
  std::vector<std::uint8_t> frame;
  fg::message_data_frame(0x01020304u, 0x1122334455667788ull, payload, sizeof payload, frame);
  const std::vector<std::uint8_t> expected = {0x01,                                            // opcode: message data
                                              0x04, 0x03, 0x02, 0x01,                          // subscription id
                                              0x88, 0x77, 0x66, 0x55, 0x44, 0x33, 0x22, 0x11,  // receive time, ns
                                              0x00, 0x01, 0x00, 0x00, 0xAA, 0xBB};             // the bytes as given
  EXPECT_EQ(frame, expected);
  EXPECT_EQ(fg::kMessageDataHeader, 13u);
}

TEST(Foxglove, ServerMessagesCarryTheSpecsFieldNames) {
  const auto info = nlohmann::json::parse(fg::server_info_json("plumb-display", "42"));
  EXPECT_EQ(info["op"], "serverInfo");
  EXPECT_EQ(info["name"], "plumb-display");
  EXPECT_TRUE(info["capabilities"].is_array());
  EXPECT_TRUE(info["capabilities"].empty());
  EXPECT_EQ(info["sessionId"], "42");

  fg::Channel c;
  c.id = 7;
  c.topic = "plumb/attitude/static";
  c.schema_name = "plumb::msg::Attitude";
  c.schema = "module plumb { };";
  const auto adv = nlohmann::json::parse(fg::advertise_json({c}));
  EXPECT_EQ(adv["op"], "advertise");
  ASSERT_EQ(adv["channels"].size(), 1u);
  EXPECT_EQ(adv["channels"][0]["id"], 7);
  EXPECT_EQ(adv["channels"][0]["topic"], "plumb/attitude/static");
  EXPECT_EQ(adv["channels"][0]["encoding"], "cdr");
  EXPECT_EQ(adv["channels"][0]["schemaName"], "plumb::msg::Attitude");
  EXPECT_EQ(adv["channels"][0]["schemaEncoding"], "omgidl");
  EXPECT_EQ(adv["channels"][0]["schema"], "module plumb { };");

  const auto unadv = nlohmann::json::parse(fg::unadvertise_json({3, 5}));
  EXPECT_EQ(unadv["op"], "unadvertise");
  EXPECT_EQ(unadv["channelIds"], nlohmann::json::array({3, 5}));
  const auto status = nlohmann::json::parse(fg::status_json(fg::StatusLevel::Warning, "careful"));
  EXPECT_EQ(status["op"], "status");
  EXPECT_EQ(status["level"], 1);
  EXPECT_EQ(status["message"], "careful");
}

TEST(Foxglove, ClientMessagesAreParsedOrRefusedWithAReason) {
  const auto sub = fg::parse_client_message(R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":3},{"id":1,"channelId":5}]})");
  ASSERT_TRUE(std::holds_alternative<fg::Subscribe>(sub));
  const auto& s = std::get<fg::Subscribe>(sub).subscriptions;
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[1].id, 1u);
  EXPECT_EQ(s[1].channel_id, 5u);
  const auto unsub = fg::parse_client_message(R"({"op":"unsubscribe","subscriptionIds":[0,1]})");
  ASSERT_TRUE(std::holds_alternative<fg::Unsubscribe>(unsub));
  EXPECT_EQ(std::get<fg::Unsubscribe>(unsub).subscription_ids, (std::vector<std::uint32_t>{0, 1}));
  const auto other = fg::parse_client_message(R"({"op":"getParameters","parameterNames":[]})");
  ASSERT_TRUE(std::holds_alternative<fg::Unsupported>(other));
  EXPECT_EQ(std::get<fg::Unsupported>(other).op, "getParameters");
  EXPECT_TRUE(std::holds_alternative<fg::Invalid>(fg::parse_client_message("{not json")));
  EXPECT_TRUE(std::holds_alternative<fg::Invalid>(fg::parse_client_message(R"({"subscriptions":[]})")));
  EXPECT_TRUE(std::holds_alternative<fg::Invalid>(fg::parse_client_message(R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":3}]})")));
  EXPECT_TRUE(std::holds_alternative<fg::Invalid>(fg::parse_client_message(R"({"op":"subscribe","subscriptions":[{"id":4294967296,"channelId":3}]})")));
  EXPECT_TRUE(std::holds_alternative<fg::Invalid>(fg::parse_client_message(R"({"op":"unsubscribe","subscriptionIds":["a"]})")));
}

TEST(FoxgloveHub, AJoiningClientGetsServerInfoThenEveryChannel) {
  FoxgloveHub hub;
  const auto a = hub.advertise("plumb/attitude/static", "plumb::msg::Attitude", "idl a");
  const auto b = hub.advertise("plumb/sensor/raw", "plumb::msg::SensorBatch", "idl b");
  EXPECT_NE(a, b);
  auto client = hub.join();
  const auto frames = fox_take(*client);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(fox_parse(frames[0])["op"], "serverInfo");
  const auto adv = fox_parse(frames[1]);
  EXPECT_EQ(adv["op"], "advertise");
  EXPECT_EQ(adv["channels"].size(), 2u);
  // A channel that appears later is advertised to the clients there.
  hub.advertise("plumb/status", "plumb::msg::ComponentStatus", "idl c");
  const auto later = fox_take(*client);
  ASSERT_EQ(later.size(), 1u);
  EXPECT_EQ(fox_parse(later[0])["channels"][0]["topic"], "plumb/status");
  EXPECT_EQ(hub.stats().channels, 3u);
  hub.leave(client);
}

TEST(FoxgloveHub, OnlySubscribedChannelsAreSentWithTheClientsSubscriptionId) {
  FoxgloveHub hub;
  const auto att = hub.advertise("plumb/attitude/static", "plumb::msg::Attitude", "idl a");
  const auto raw = hub.advertise("plumb/sensor/raw", "plumb::msg::SensorBatch", "idl b");
  auto client = hub.join();
  fox_take(*client);
  EXPECT_TRUE(hub.wanted().empty());
  hub.publish(att, 1, fox_bytes({9}));  // nobody subscribed: goes nowhere
  hub.receive(client, R"({"op":"subscribe","subscriptions":[{"id":40,"channelId":)" + std::to_string(raw) + "}]}");
  EXPECT_EQ(hub.wanted(), (std::set<std::uint32_t>{raw}));
  hub.publish(att, 2, fox_bytes({8}));
  hub.publish(raw, 3, fox_bytes({7, 6}));
  const auto frames = fox_take(*client);
  ASSERT_EQ(frames.size(), 1u);
  ASSERT_TRUE(frames[0].binary);
  const std::vector<std::uint8_t> expected = {1, 40, 0, 0, 0, 3, 0, 0, 0, 0, 0, 0, 0, 7, 6};
  EXPECT_EQ(frames[0].data, expected);
  // After unsubscribing, nothing more of it, and nothing the reader no longer needs.
  hub.receive(client, R"({"op":"unsubscribe","subscriptionIds":[40]})");
  EXPECT_TRUE(hub.wanted().empty());
  hub.leave(client);
}

TEST(FoxgloveHub, ASlowClientLosesItsOldestMessagesCountedAndKeepsTheNewest) {
  FoxgloveOptions o;
  o.queue = 3;
  FoxgloveHub hub(o);
  const auto raw = hub.advertise("plumb/sensor/raw", "plumb::msg::SensorBatch", "idl b");
  auto slow = hub.join();
  auto fast = hub.join();
  fox_take(*slow);
  fox_take(*fast);
  const std::string subscribe = R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":)" + std::to_string(raw) + "}]}";
  hub.receive(slow, subscribe);
  hub.receive(fast, subscribe);
  for (std::uint8_t i = 0; i < 10; ++i) {
    hub.publish(raw, i, fox_bytes({i}));
    if (i % 2 == 1) {
      EXPECT_EQ(fox_take(*fast).size(), 2u);  // a client that keeps up loses nothing
    }
  }
  EXPECT_EQ(slow->dropped(), 7u);
  EXPECT_EQ(fast->dropped(), 0u);
  const auto frames = fox_take(*slow);
  ASSERT_EQ(frames.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(static_cast<std::size_t>(frames[k].data.back()), 7 + k);  // the newest, in order
  EXPECT_EQ(hub.stats().dropped, 7u);
  hub.leave(slow);
  EXPECT_EQ(hub.stats().dropped, 7u);  // still counted once the client has gone
  EXPECT_EQ(hub.stats().clients, 1u);
  hub.leave(fast);
}

TEST(FoxgloveHub, AnUnadvertisedChannelEndsItsSubscriptionsAndComesBackWithItsId) {
  FoxgloveHub hub;
  const auto att = hub.advertise("plumb/attitude/static", "plumb::msg::Attitude", "idl a");
  auto client = hub.join();
  fox_take(*client);
  hub.receive(client, R"({"op":"subscribe","subscriptions":[{"id":5,"channelId":)" + std::to_string(att) + "}]}");
  hub.publish(att, 1, fox_bytes({1}));
  hub.unadvertise("plumb/attitude/static");
  EXPECT_TRUE(hub.wanted().empty());
  const auto frames = fox_take(*client);
  ASSERT_EQ(frames.size(), 1u);  // the queued message went with the channel: nothing after its unadvertise
  const auto unadv = fox_parse(frames[0]);
  EXPECT_EQ(unadv["op"], "unadvertise");
  EXPECT_EQ(unadv["channelIds"], nlohmann::json::array({att}));
  EXPECT_EQ(hub.stats().channels, 0u);
  // The same topic and type again: the same id (the protocol allows reuse only then); another type: a new one.
  EXPECT_EQ(hub.advertise("plumb/attitude/static", "plumb::msg::Attitude", "idl a"), att);
  hub.unadvertise("plumb/attitude/static");
  EXPECT_NE(hub.advertise("plumb/attitude/static", "plumb::msg::Truth", "idl t"), att);
  hub.leave(client);
}

TEST(FoxgloveHub, WhatCannotBeDoneIsAnsweredWithAStatus) {
  FoxgloveHub hub;
  const auto att = hub.advertise("plumb/attitude/static", "plumb::msg::Attitude", "idl a");
  const auto raw = hub.advertise("plumb/sensor/raw", "plumb::msg::SensorBatch", "idl b");
  auto client = hub.join();
  fox_take(*client);
  const std::string a = std::to_string(att), r = std::to_string(raw);
  hub.receive(client, R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":999}]})");
  hub.receive(client, R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":)" + a + R"(},{"id":1,"channelId":)" + r + "}]}");
  hub.receive(client, R"({"op":"subscribe","subscriptions":[{"id":2,"channelId":)" + a + "}]}");
  hub.receive(client, R"({"op":"advertise","channels":[]})");
  hub.receive(client, "[]");
  const auto frames = fox_take(*client);
  ASSERT_EQ(frames.size(), 5u);
  const int levels[] = {1, 2, 1, 1, 2};  // unknown channel, id in use, channel subscribed twice, unsupported, invalid
  for (std::size_t k = 0; k < 5; ++k) {
    const auto j = fox_parse(frames[k]);
    EXPECT_EQ(j["op"], "status");
    EXPECT_EQ(j["level"], levels[k]) << j.dump();
  }
  EXPECT_EQ(hub.wanted(), (std::set<std::uint32_t>{att}));  // the one subscription that was valid
  hub.leave(client);
}

}  // namespace
}  // namespace plumb::display_component
