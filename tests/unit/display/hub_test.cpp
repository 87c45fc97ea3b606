// plumb-display's hub: what a slow browser loses (the oldest estimates, counted, never the latest),
// what a browser that joins gets (history, latest estimates, statuses, stations), the throttle and
// the heartbeat of the frames, and the JSON the page reads.
#include "hub.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "json.hpp"

namespace plumb::display_component {
namespace {

HistoryPoint point(double rx_ms, double inc) {
  HistoryPoint p;
  p.rx_ms = rx_ms;
  p.inclination = inc;
  p.flags = 7;
  return p;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(DisplayHub, StalledBrowserKeepsTheLatestEstimatesAndCountsTheRest) {
  HubOptions o;
  o.backlog = 4;
  o.min_gap = std::chrono::milliseconds(0);
  Hub hub(o);
  auto stalled = hub.join();
  auto reading = hub.join();
  ASSERT_TRUE(stalled->next());  // the hello frames
  ASSERT_TRUE(reading->next());
  for (int i = 0; i < 100; ++i) {
    hub.attitude("rig/a", "{\"v\":" + std::to_string(i) + "}", point(1000.0 * i, 1));
    if (i % 3 == 2) {
      const auto frame = reading->next();  // a browser that keeps up gets every estimate
      ASSERT_TRUE(frame);
      EXPECT_EQ(count(*frame, "{\"v\":"), 3) << *frame;
    }
  }
  EXPECT_EQ(reading->dropped(), 0u);
  EXPECT_EQ(stalled->dropped(), 96u);
  const auto frame = stalled->next();
  ASSERT_TRUE(frame);
  EXPECT_EQ(count(*frame, "{\"v\":"), 4);
  EXPECT_NE(frame->find("{\"v\":99}"), std::string::npos) << "the latest estimate is never dropped";
  EXPECT_NE(frame->find("\"drops\":96"), std::string::npos);
  EXPECT_EQ(hub.stats().browsers, 2u);
  EXPECT_EQ(hub.stats().attitudes, 100u);
}

TEST(DisplayHub, JoiningBrowserGetsHistoryLatestStatusesAndStations) {
  Hub hub;
  hub.attitude("rig/a", "{\"est\":1}", point(1000, 1.5));
  hub.attitude("rig/a", "{\"est\":2}", point(2000, 1.6));
  hub.status("plumb-sim@host", "{\"s\":1}");
  hub.station("rig#0", "{\"i\":0}");
  hub.station("rig#1", "{\"i\":1}");
  auto box = hub.join();
  const auto hello = box->next();
  ASSERT_TRUE(hello);
  EXPECT_NE(hello->find("\"type\":\"hello\""), std::string::npos);
  EXPECT_NE(hello->find("\"rig/a\":[[1000,1.5,"), std::string::npos) << *hello;
  EXPECT_NE(hello->find("[2000,1.6,"), std::string::npos) << *hello;
  const auto update = box->next();
  ASSERT_TRUE(update);
  EXPECT_EQ(count(*update, "{\"est\":"), 1) << "the latest estimate only";
  EXPECT_NE(update->find("{\"est\":2}"), std::string::npos);
  EXPECT_NE(update->find("{\"s\":1}"), std::string::npos);
  EXPECT_NE(update->find("{\"i\":0},{\"i\":1}"), std::string::npos) << *update;
}

// A clearance is a state: the newest per tool and offset well, to a browser already there and to
// one that joins later.
TEST(DisplayHub, ClearancesKeepTheNewestPerOffsetWell) {
  Hub hub;
  auto early = hub.join();
  ASSERT_TRUE(early->next());  // hello
  hub.clearance("rig/offset-1", "{\"sf\":3}");
  hub.clearance("rig/offset-1", "{\"sf\":2}");
  hub.clearance("rig/offset-2", "{\"sf\":9}");
  const auto update = early->next();
  ASSERT_TRUE(update);
  EXPECT_NE(update->find("\"clearance\":[{\"sf\":2},{\"sf\":9}]"), std::string::npos) << *update;
  auto late = hub.join();
  ASSERT_TRUE(late->next());  // hello
  const auto first = late->next();
  ASSERT_TRUE(first);
  EXPECT_EQ(count(*first, "{\"sf\":"), 2) << *first;
  EXPECT_EQ(first->find("{\"sf\":3}"), std::string::npos) << "an older clearance of the same well is gone";
  EXPECT_EQ(hub.stats().clearances, 3u);
}

// A plugin unloaded (its topic without a writer): its card leaves the pages there, and a page that
// opens later never gets it.
TEST(DisplayHub, ForgottenStreamLeavesThePagesAndIsNotSentToLaterOnes) {
  HubOptions o;
  o.min_gap = std::chrono::milliseconds(0);
  Hub hub(o);
  auto early = hub.join();
  ASSERT_TRUE(early->next());  // hello
  hub.attitude("rig/integral", "{\"est\":\"integral\"}", point(1000, 1));
  hub.attitude("rig/compensated", "{\"est\":\"compensated\"}", point(1000, 1));
  hub.forget_attitude("rig/integral");
  const auto update = early->next();
  ASSERT_TRUE(update);
  EXPECT_EQ(update->find("{\"est\":\"integral\"}"), std::string::npos) << "its queued estimate goes with it: " << *update;
  EXPECT_NE(update->find("\"gone\":[\"rig/integral\"]"), std::string::npos) << *update;
  hub.attitude("rig/compensated", "{}", point(2000, 1));
  const auto next = early->next();
  ASSERT_TRUE(next);
  EXPECT_NE(next->find("\"gone\":[]"), std::string::npos) << "said once: " << *next;
  auto late = hub.join();
  const auto hello = late->next();
  ASSERT_TRUE(hello);
  EXPECT_EQ(hello->find("rig/integral"), std::string::npos) << "no history of it: " << *hello;
  const auto first = late->next();
  ASSERT_TRUE(first);
  EXPECT_EQ(first->find("integral"), std::string::npos) << *first;
}

TEST(DisplayHub, FramesAreThrottledAndIdleLinksGetHeartbeats) {
  HubOptions o;
  o.min_gap = std::chrono::milliseconds(50);
  o.heartbeat = std::chrono::milliseconds(200);
  Hub hub(o);
  auto box = hub.join();
  ASSERT_TRUE(box->next());  // hello
  hub.attitude("rig/a", "{}", point(0, 1));
  auto t0 = std::chrono::steady_clock::now();
  ASSERT_TRUE(box->next());
  EXPECT_GE(std::chrono::steady_clock::now() - t0, std::chrono::milliseconds(45)) << "at most one frame per min_gap";
  t0 = std::chrono::steady_clock::now();
  const auto idle = box->next();  // nothing published: a heartbeat after 200 ms
  ASSERT_TRUE(idle);
  EXPECT_GE(std::chrono::steady_clock::now() - t0, std::chrono::milliseconds(150));
  EXPECT_NE(idle->find("\"att\":[]"), std::string::npos);
  hub.leave(box);
  EXPECT_FALSE(box->next()) << "a browser that left gets nothing more";
  EXPECT_EQ(hub.stats().browsers, 0u);
}

TEST(DisplayJson, StringsAreEscapedAndNonFiniteNumbersAreNull) {
  std::string out;
  append_json_string(out, "a\"b\\c\nd\x01");
  EXPECT_EQ(out, "\"a\\\"b\\\\c\\nd\\u0001\"");
  out.clear();
  append_json_number(out, std::nan(""), 2);
  append_json_number(out, 1.0 / 0.0, 2);
  append_json_number(out, -1.234, 2);
  EXPECT_EQ(out, "nullnull-1.23");
  topics::Attitude a;
  a.tool_id = "rig";
  a.estimator = "compensated";
  a.inclination_deg = 2.0;
  a.reason = "too \"fast\"";
  const std::string json = attitude_json(a, "rig/compensated", 123.0);
  EXPECT_NE(json.find("\"k\":\"rig/compensated\",\"tool\":\"rig\",\"est\":\"compensated\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"inc\":2.0,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"why\":\"too \\\"fast\\\"\""), std::string::npos);
}

}  // namespace
}  // namespace plumb::display_component
