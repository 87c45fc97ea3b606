// The runner that every host shares: estimates carry the plugin's name, parameters reach the
// estimator that declares them, counters add up, reset starts over.
#include <gtest/gtest.h>

#include "plumb/estimator/runner.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace plumb::estimator {
namespace {

// Emits one estimate every `every` samples; valid when the sample's f.x is positive.
class Counting final : public Estimator {
 public:
  explicit Counting(bool gyro) : gyro_(gyro) {}
  Info info() const override {
    Info i;
    i.name = "whatever";  // the runner labels by the slot's name, not by this
    i.parameters = {{"every", "2", ""}};
    i.uses_gyro = gyro_;
    return i;
  }
  void configure(const Parameters& p) override {
    every_ = p.contains("every") ? std::stoi(p.at("every")) : 2;
    seen_ = 0;
  }
  void push(std::span<const Sample> samples, std::vector<Estimate>& out) override {
    for (const auto& s : samples) {
      if (++seen_ % every_ != 0) continue;
      Estimate e;
      e.valid = s.f.x() > 0;
      e.t_end = s.t;
      out.push_back(e);
    }
  }
  void flush(std::vector<Estimate>& out) override {
    if (seen_ % every_ != 0) out.push_back(Estimate{});
    seen_ = 0;
  }
  Counters counters() const override { return {{"seen", seen_}}; }

 private:
  bool gyro_;
  int every_ = 2;
  std::uint64_t seen_ = 0;
};

EstimatorPtr make(bool gyro) { return EstimatorPtr(new Counting(gyro), [](Estimator* e) { delete e; }); }

std::vector<Sample> samples(int n, double fx) {
  std::vector<Sample> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)].t = i, out[static_cast<std::size_t>(i)].f.x() = fx;
  return out;
}

TEST(Runner, LabelsEveryEstimateWithItsSlotAndCountsThem) {
  Runner runner;
  runner.add("a", make(false));
  runner.add("b", make(true));
  runner.configure({{{"every", "2"}}, {{"every", "3"}}});
  std::map<std::string, int> got;
  const auto sink = [&](const Runner::Slot& slot, Estimate& e) {
    EXPECT_EQ(e.estimator, slot.name);
    ++got[slot.name];
  };
  runner.push(samples(6, 1.0), sink);
  EXPECT_EQ(got["a"], 3);
  EXPECT_EQ(got["b"], 2);
  runner.push(samples(1, -1.0), sink);
  runner.flush(sink);  // a: 7th sample leaves a partial window; b: likewise
  EXPECT_EQ(runner.slots()[0].estimates, 4u);
  EXPECT_EQ(runner.slots()[0].invalid, 1u);
  EXPECT_EQ(runner.needing_gyro(), std::vector<std::string>{"b"});
  const auto counters = runner.counters();
  EXPECT_NE(std::find(counters.begin(), counters.end(), std::pair<std::string, std::uint64_t>{"a.estimates", 4}),
            counters.end());
}

TEST(Runner, AssignmentsGoOnlyToTheEstimatorsThatDeclareThem) {
  Runner runner;
  runner.add("a", make(false));
  runner.configure(std::vector<std::string>{"every=5"}, std::nullopt);
  EXPECT_EQ(runner.slots()[0].parameters.at("every"), "5");
  EXPECT_THROW(runner.configure(std::vector<std::string>{"evry=5"}, std::nullopt), ParameterError);
}

TEST(Runner, ResetStartsEachEstimatorOverWithItsParameters) {
  Runner runner;
  runner.add("a", make(false));
  runner.configure({{{"every", "4"}}});
  int n = 0;
  const auto sink = [&](const Runner::Slot&, Estimate&) { ++n; };
  runner.push(samples(3, 1.0), sink);
  runner.reset();
  runner.push(samples(3, 1.0), sink);
  EXPECT_EQ(n, 0);  // without the reset the 4th sample would have completed a window
  runner.push(samples(1, 1.0), sink);
  EXPECT_EQ(n, 1);
}

// Gives one estimate per push, as a plugin fills it: numbers everywhere, an unknown sigma as 0.
class Filled final : public Estimator {
 public:
  explicit Filled(Estimate e) : e_(std::move(e)) {}
  Info info() const override { return Info{}; }
  void configure(const Parameters&) override {}
  void push(std::span<const Sample>, std::vector<Estimate>& out) override { out.push_back(e_); }
  void flush(std::vector<Estimate>&) override {}
  Counters counters() const override { return {}; }

 private:
  Estimate e_;
};

Estimate delivered(const Estimate& made) {
  Runner runner;
  runner.add("p", EstimatorPtr(new Filled(made), [](Estimator* e) { delete e; }));
  std::vector<Estimate> out;
  runner.push(samples(1, 1), [&](const Runner::Slot&, Estimate& e) { out.push_back(e); });
  return out.at(0);
}

Estimate filled(bool valid, bool azimuth_valid, bool toolface_valid) {
  Estimate e;
  e.valid = valid, e.azimuth_valid = azimuth_valid, e.toolface_valid = toolface_valid;
  e.inclination_deg = 4e-16, e.azimuth_deg = 12, e.gravity_toolface_deg = 30, e.magnetic_toolface_deg = 40;
  e.inclination_sd_deg = 0.01, e.azimuth_sd_deg = 0, e.toolface_sd_deg = 0.5;  // 0: not estimated
  e.dip_deg = 90, e.total_g = 9.8, e.total_b = 48, e.rpm = 60;
  e.reason = valid ? "" : "platform rotating";
  return e;
}

TEST(Runner, WhatAnInvalidEstimateDidNotMeasureIsNaN) {
  const Estimate e = delivered(filled(false, false, false));
  for (double v : {e.inclination_deg, e.azimuth_deg, e.gravity_toolface_deg, e.magnetic_toolface_deg, e.inclination_sd_deg,
                   e.azimuth_sd_deg, e.toolface_sd_deg, e.dip_deg, e.total_g, e.total_b})
    EXPECT_TRUE(std::isnan(v)) << v;
  EXPECT_EQ(e.rpm, 60);  // the platform's speed is measured however the attitude fails
  EXPECT_EQ(e.reason, "platform rotating");
}

// A navigator before alignment: no position, velocity or their sigma (it fills zeros).
TEST(Runner, AnInvalidNavigationRowHasNoPositionOrVelocity) {
  Estimate made = filled(false, false, false);
  made.navigation = NavigationState();
  const Estimate e = delivered(made);
  ASSERT_TRUE(e.navigation.has_value());
  for (const auto* a : {&e.navigation->position_m, &e.navigation->velocity_mps, &e.navigation->position_sd_m,
                        &e.navigation->velocity_sd_mps})
    for (double v : *a) EXPECT_TRUE(std::isnan(v)) << v;
}

TEST(Runner, AnAngleMarkedInvalidAndAnUnknownSigmaAreNaN) {
  const Estimate e = delivered(filled(true, false, true));
  EXPECT_EQ(e.inclination_deg, 4e-16);
  EXPECT_EQ(e.inclination_sd_deg, 0.01);
  EXPECT_TRUE(std::isnan(e.azimuth_deg));
  EXPECT_TRUE(std::isnan(e.azimuth_sd_deg));
  EXPECT_EQ(e.gravity_toolface_deg, 30);
  EXPECT_EQ(e.toolface_sd_deg, 0.5);
  const Estimate f = delivered(filled(true, true, false));
  EXPECT_EQ(f.azimuth_deg, 12);
  EXPECT_TRUE(std::isnan(f.azimuth_sd_deg));  // reported as 0: not estimated
  EXPECT_TRUE(std::isnan(f.gravity_toolface_deg));
  EXPECT_TRUE(std::isnan(f.toolface_sd_deg));
  EXPECT_EQ(f.magnetic_toolface_deg, 40);
}


// The estimate times a slot published, for the run-time changes below.
std::vector<double> times_of(const std::map<std::string, std::vector<double>>& got, const std::string& name) {
  const auto it = got.find(name);
  return it == got.end() ? std::vector<double>{} : it->second;
}

std::vector<Sample> samples_from(int first, int n) {
  std::vector<Sample> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)].t = first + i, out[static_cast<std::size_t>(i)].f.x() = 1;
  return out;
}

// A slot added, re-tuned and removed while samples flow: the other slot's windows go on one after
// the other, none missing or cut short.
TEST(Runner, AddReconfigureAndRemoveOneSlotLeaveTheOthersWindowsWhole) {
  Runner runner;
  runner.add("a", make(false));
  runner.configure({{{"every", "4"}}});
  std::map<std::string, std::vector<double>> got;
  const auto sink = [&](const Runner::Slot& slot, Estimate& e) { got[slot.name].push_back(e.t_end); };
  runner.push(samples_from(0, 6), sink);  // a: window ends at t 3; two samples open
  runner.add("b", make(false));
  runner.reconfigure("b", {{"every", "3"}}, sink);  // a new slot: nothing open, nothing flushed
  EXPECT_TRUE(times_of(got, "b").empty());
  runner.push(samples_from(6, 6), sink);  // b's windows: 6-8, 9-11
  EXPECT_EQ(times_of(got, "b"), (std::vector<double>{8, 11}));
  runner.push(samples_from(12, 1), sink);  // b has t 12 open
  runner.reconfigure("b", {{"every", "2"}}, sink);  // b's open window (t 12) closes now, as a partial
  ASSERT_EQ(runner.find("b")->parameters.at("every"), "2");
  runner.push(samples_from(13, 4), sink);  // b: 13-14, 15-16
  EXPECT_EQ(times_of(got, "b").size(), 5u);  // 8, 11, the partial, 14, 16
  EXPECT_EQ(times_of(got, "b").back(), 16);
  EXPECT_TRUE(runner.remove("b", sink));
  EXPECT_FALSE(runner.remove("b", sink));
  EXPECT_EQ(runner.find("b"), nullptr);
  runner.push(samples_from(17, 7), sink);  // up to t 23
  // a never noticed: one window every 4 samples from the start, t 3, 7, 11, ..., 23.
  std::vector<double> expected;
  for (double t = 3; t <= 23; t += 4) expected.push_back(t);
  EXPECT_EQ(times_of(got, "a"), expected);
  EXPECT_EQ(runner.slots().size(), 1u);
  EXPECT_EQ(runner.slots()[0].estimates, expected.size());
  EXPECT_THROW(runner.reconfigure("nobody", {}, sink), std::out_of_range);
}

}  // namespace
}  // namespace plumb::estimator
