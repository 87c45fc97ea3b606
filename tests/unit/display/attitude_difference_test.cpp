// Two plugins of one tool: each one's difference from the reference (the first by name), computed
// once in plumb-display for both readers: the page (with each estimate's JSON; the page only draws
// it, page_test.js) and Foxglove (a JSON channel of its own).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "attitude_difference.hpp"
#include "json.hpp"

namespace plumb::display_component {
namespace {

topics::Attitude diff_attitude(const std::string& est, double inc, double azi, double tf, double t_s, double rpm = 0) {
  topics::Attitude a;
  a.tool_id = "sim";
  a.estimator = est;
  a.window_end_ns = static_cast<std::int64_t>(t_s * 1e9);
  a.inclination_deg = inc;
  a.azimuth_deg = azi;
  a.gravity_toolface_deg = tf;
  a.rpm = rpm;
  a.inclination_sd_deg = 0.03;
  a.azimuth_sd_deg = 0.3;
  a.toolface_sd_deg = 0.4;
  a.flags = topics::ATTITUDE_VALID | topics::ATTITUDE_AZIMUTH_VALID | topics::ATTITUDE_TOOLFACE_VALID;
  return a;
}

TEST(AttitudeDifference, EachPluginAgainstTheFirstByNameAnglesWrappedSigmasCombined) {
  AttitudeDifferences diffs;
  EXPECT_FALSE(diffs.update(diff_attitude("static", 2.0, 359, 350, 10), 100));  // alone: nothing to compare
  EXPECT_FALSE(diffs.update(diff_attitude("compensated", 2.02, 1, 340, 10), 100));  // the reference now
  const auto d = diffs.update(diff_attitude("static", 2.0, 359, 350, 10), 100.1);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->reference, "compensated");
  EXPECT_NEAR(d->inclination->degrees, -0.02, 1e-12);
  EXPECT_NEAR(d->inclination->sd_degrees, std::hypot(0.03, 0.03), 1e-12);
  EXPECT_NEAR(d->azimuth->degrees, -2, 1e-9);  // 359 - 1 wraps
  EXPECT_NEAR(d->toolface->degrees, 10, 1e-9);
}

// What the page's own differences() checked before the display computed them for it: several
// plugins and tools, a reference that gives no toolface, azimuths either side of north, a stale one.
TEST(AttitudeDifference, ReferencePerToolAnAngleEitherLacksLeftOutStaleOnesIgnored) {
  const auto of_tool = [](const std::string& tool, const std::string& est, double inc, double azi, double tf,
                          std::uint32_t flags) {
    topics::Attitude a = diff_attitude(est, inc, azi, tf, 10);
    a.tool_id = tool;
    a.flags = flags;
    return a;
  };
  constexpr std::uint32_t all = 7, no_toolface = 3;
  AttitudeDifferences diffs;
  EXPECT_FALSE(diffs.update(of_tool("sim", "zz", 9, 9, 9, all), 90));  // heard from 10 s before the rest
  EXPECT_FALSE(diffs.update(of_tool("other", "static", 5, 80, 0, all), 100)) << "a tool with one plugin: none";
  EXPECT_FALSE(diffs.update(of_tool("sim", "static", 2.0, 359, 10, all), 100)) << "zz (10 s before) is stale: static alone";
  EXPECT_FALSE(diffs.update(of_tool("sim", "compensated", 1.98, 0, 10, no_toolface), 100.1)) << "the reference: none";
  const auto integral = diffs.update(of_tool("sim", "integral", 2.05, 1, 350, all), 100.2);
  ASSERT_TRUE(integral);
  EXPECT_EQ(integral->reference, "compensated");
  EXPECT_EQ(integral->tool, "sim");
  EXPECT_NEAR(integral->inclination->degrees, 0.07, 1e-9);
  EXPECT_NEAR(integral->azimuth->degrees, 1, 1e-9) << "1 minus 0";
  EXPECT_FALSE(integral->toolface) << "the reference gives no toolface";
  const auto stat = diffs.update(of_tool("sim", "static", 2.0, 359, 10, all), 100.3);
  ASSERT_TRUE(stat);
  EXPECT_EQ(stat->reference, "compensated") << "zz (heard 10.3 s ago) is stale";
  EXPECT_NEAR(stat->azimuth->degrees, -1, 1e-9) << "359 minus 0 wraps";
  EXPECT_FALSE(diffs.update(of_tool("other", "static", 5, 80, 0, all), 100.4)) << "still alone on its tool";
}

TEST(AttitudeDifference, ToolfaceCarriedToTheReferencesWindowEndOrLeftOut) {
  AttitudeDifferences diffs;
  diffs.update(diff_attitude("compensated", 2, 10, 350, 10), 100);
  // Ends 0.5 s later, turning 10 rpm (60 deg/s): 10 deg then is -20 deg at the reference's end.
  auto d = diffs.update(diff_attitude("integral", 2, 10, 10, 10.5, 10), 100.2);
  ASSERT_TRUE(d && d->toolface);
  EXPECT_NEAR(d->toolface->degrees, -10, 1e-6);
  d = diffs.update(diff_attitude("integral", 2, 10, 10, 11.5, 10), 100.3);  // 1.5 s apart: no toolface
  ASSERT_TRUE(d);
  EXPECT_FALSE(d->toolface);
  EXPECT_TRUE(d->inclination);
  topics::Attitude invalid = diff_attitude("static", 0, 0, 0, 10);
  invalid.flags = 0;
  d = diffs.update(invalid, 100.3);
  ASSERT_TRUE(d);
  EXPECT_FALSE(d->inclination || d->azimuth || d->toolface);
  // The reference silent for more than 5 s (unloaded): the next by name takes its place.
  d = diffs.update(diff_attitude("static", 2, 10, 10, 20), 106);
  EXPECT_FALSE(d) << "integral (heard at 100.3 s) is stale too: static is alone";
}

TEST(AttitudeDifference, PublishedOnAJsonChannelPerToolAndPlugin) {
  FoxgloveHub hub;
  PluginDifferences fox(&hub);
  const auto client = hub.join();
  fox.attitude(diff_attitude("compensated", 2, 10, 350, 10), 100000);
  fox.attitude(diff_attitude("integral", 2.5, 10, 350, 10), 100100);
  std::vector<FoxgloveFrame> frames;
  ASSERT_TRUE(client->next(frames, 100));
  nlohmann::json advertised;
  for (const auto& f : frames)
    if (!f.binary && nlohmann::json::parse(f.text)["op"] == "advertise") advertised = nlohmann::json::parse(f.text);
  ASSERT_FALSE(advertised.is_null());
  const auto& channel = advertised["channels"][0];
  EXPECT_EQ(channel["topic"], "plumb-display/difference/sim/integral");
  EXPECT_EQ(channel["encoding"], "json");
  EXPECT_EQ(channel["schemaEncoding"], "jsonschema");
  EXPECT_EQ(nlohmann::json::parse(channel["schema"].get<std::string>())["type"], "object");
  AttitudeDifference d;
  d.tool = "sim";
  d.estimator = "integral";
  d.reference = "compensated";
  d.inclination = AngleDifference{0.5, 0.04};
  const auto message = nlohmann::json::parse(difference_json(d));
  EXPECT_EQ(message["reference"], "compensated");
  EXPECT_DOUBLE_EQ(message["inclination"]["deg"].get<double>(), 0.5);
  EXPECT_TRUE(message["toolface"].is_null()) << "an angle not compared is null";
}

std::vector<std::string> difference_ops(FoxgloveClient& client, const std::string& op) {
  std::vector<FoxgloveFrame> frames;
  std::vector<std::string> out;
  if (!client.next(frames, 100)) return out;
  for (const auto& f : frames) {
    if (f.binary) continue;
    const auto j = nlohmann::json::parse(f.text);
    if (j["op"] != op) continue;
    if (op == "advertise")
      for (const auto& c : j["channels"]) out.push_back(c["topic"].get<std::string>() + "#" + std::to_string(c["id"].get<int>()));
    if (op == "unadvertise")
      for (const auto& id : j["channelIds"]) out.push_back("#" + std::to_string(id.get<int>()));
  }
  return out;
}

// A difference channel lives as long as its plugin has a difference: its topic's last writer gone
// (unloaded) takes it away, and so does the plugin becoming its tool's reference (the reference it
// was compared with unloaded).
TEST(AttitudeDifference, ChannelUnadvertisedWhenItsPluginIsGoneOrBecomesTheReference) {
  FoxgloveHub hub;
  PluginDifferences diffs(&hub);
  const auto client = hub.join();
  EXPECT_TRUE(difference_ops(*client, "advertise").empty()) << "serverInfo only: nothing advertised yet";
  diffs.attitude(diff_attitude("compensated", 2, 10, 350, 10), 100000);
  diffs.attitude(diff_attitude("integral", 2, 10, 350, 10), 100100);
  diffs.attitude(diff_attitude("static", 2, 10, 350, 10), 100200);
  const auto advertised = difference_ops(*client, "advertise");
  ASSERT_EQ(advertised.size(), 2u);
  EXPECT_EQ(advertised[0].rfind("plumb-display/difference/sim/integral#", 0), 0u) << advertised[0];
  const std::string integral_id = advertised[0].substr(advertised[0].find('#'));
  const std::string static_id = advertised[1].substr(advertised[1].find('#'));
  diffs.gone("sim", "integral");
  EXPECT_EQ(difference_ops(*client, "unadvertise"), std::vector<std::string>{integral_id});
  EXPECT_EQ(hub.stats().channels, 1u);
  diffs.gone("sim", "compensated");  // the reference: it had no channel
  EXPECT_TRUE(diffs.attitude(diff_attitude("zz", 2, 10, 350, 10), 100300)) << "against static now";
  EXPECT_FALSE(diffs.attitude(diff_attitude("static", 2, 10, 350, 10), 100400)) << "the reference now";
  const auto ops = difference_ops(*client, "unadvertise");
  EXPECT_EQ(ops, std::vector<std::string>{static_id}) << "static has no difference any more";
  EXPECT_EQ(hub.stats().channels, 1u) << "zz's";
  // integral loaded again is the reference (the first by name): static has a difference again, on
  // its channel again, with its old id (the protocol allows the reuse for the same type).
  EXPECT_FALSE(diffs.attitude(diff_attitude("integral", 2, 10, 350, 10), 100500));
  EXPECT_TRUE(diffs.attitude(diff_attitude("static", 2, 10, 350, 10), 100600));
  const auto again = difference_ops(*client, "advertise");
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0], "plumb-display/difference/sim/static" + static_id);
}

// The page draws what it is given: each estimate's JSON carries its difference (page_test.js reads
// this form), null for the reference.
TEST(AttitudeDifference, EachEstimatesPageJsonCarriesItsDifference) {
  PluginDifferences diffs;  // no Foxglove: the page's still computed
  const topics::Attitude reference = diff_attitude("compensated", 2, 10, 350, 10);
  const topics::Attitude integral = diff_attitude("integral", 2.07, 9, 355, 10);
  EXPECT_FALSE(diffs.attitude(reference, 100000));
  const auto d = diffs.attitude(integral, 100100);
  ASSERT_TRUE(d);
  const auto with = nlohmann::json::parse(attitude_json(integral, "sim/integral", 100100, d));
  EXPECT_EQ(with["diff"]["ref"], "compensated");
  EXPECT_NEAR(with["diff"]["inc"]["d"].get<double>(), 0.07, 1e-9);
  EXPECT_NEAR(with["diff"]["inc"]["sd"].get<double>(), 0.0424, 1e-9) << "hypot(0.03, 0.03) to 4 places";
  EXPECT_NEAR(with["diff"]["azi"]["d"].get<double>(), -1, 1e-9);
  EXPECT_NEAR(with["diff"]["tf"]["d"].get<double>(), 5, 1e-9);
  const auto own = nlohmann::json::parse(attitude_json(reference, "sim/compensated", 100000, std::nullopt));
  ASSERT_TRUE(own.contains("diff"));
  EXPECT_TRUE(own["diff"].is_null());
  AttitudeDifference partial;
  partial.reference = "compensated";
  partial.azimuth = AngleDifference{1, 0.4};
  const auto some = nlohmann::json::parse(attitude_json(integral, "sim/integral", 100100, partial));
  EXPECT_TRUE(some["diff"]["inc"].is_null() && some["diff"]["tf"].is_null()) << some.dump();
}

}  // namespace
}  // namespace plumb::display_component
