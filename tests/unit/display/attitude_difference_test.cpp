// Two plugins of one tool on Foxglove: each one's difference from the reference (the first by name),
// as the page computes it (page_test.js checks the page's), on a JSON channel of its own.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "attitude_difference.hpp"

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
  FoxgloveDifferences fox(hub);
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

}  // namespace
}  // namespace plumb::display_component
