// Bad input: bad samples are rejected and counted, bad windows are reported invalid
// with a reason, and no output is ever non-finite.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "estimator_test_support.hpp"
#include "plumb/core/attitude.hpp"

namespace plumb {
namespace {

std::vector<Sample> clean(double rpm = 60, double inc = 2, double az = 50, double seconds = 10) {
  sim::Scenario s = sim::Scenario::reference(inc, az, rpm, 20, 3);
  s.duration_s = seconds;
  return test::simulate(s);
}

struct PluginRun {
  std::vector<Estimate> estimates;
  estimator::Counters counters;
};

PluginRun run(const std::string& plugin, const std::vector<Sample>& samples, estimator::Parameters params = {{"window", "0"}},
        std::size_t chunk = 0) {
  auto e = estimator::load_estimator(plugin);
  e->configure(params);
  PluginRun r;
  if (chunk == 0) chunk = samples.size();
  for (std::size_t i = 0; i < samples.size(); i += chunk) {
    e->push(std::span(samples).subspan(i, std::min(chunk, samples.size() - i)), r.estimates);
  }
  e->flush(r.estimates);
  r.counters = e->counters();
  for (const auto& est : r.estimates) EXPECT_TRUE(est.all_finite()) << plugin;
  return r;
}


TEST(EstimatorBadInput, NonFiniteSaturatedAndFlaggedSamplesAreRejectedAndCounted) {
  for (const char* plugin : test::kAllPlugins) {
    const double rpm = std::string(plugin) == "static" ? 0 : 60;
    auto samples = clean(rpm);
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    samples[100].f.x() = nan;
    samples[200].b.z() = inf;
    samples[300].t = nan;
    samples[400].flags |= flags::kAccelSaturated;
    samples[500].flags |= flags::kMagSaturated;
    samples[600].flags |= flags::kOutOfRange;
    samples[700].flags |= flags::kNotFinite;
    samples[800].t = samples[799].t - 1;  // time going backwards
    const PluginRun r = run(plugin, samples);
    EXPECT_EQ(r.counters.at("rejected_non_finite"), 4u) << plugin;
    EXPECT_EQ(r.counters.at("rejected_saturated"), 2u);
    EXPECT_EQ(r.counters.at("rejected_out_of_range"), 1u);
    EXPECT_EQ(r.counters.at("rejected_time_backwards"), 1u);
    EXPECT_EQ(r.counters.at("samples_accepted"), samples.size() - 8);
    ASSERT_EQ(r.estimates.size(), 1u);
    EXPECT_TRUE(r.estimates[0].valid) << r.estimates[0].reason;
    // The remaining 992 samples still give an estimate within a few bounds (0.18 deg at SNR 20).
    EXPECT_NEAR(r.estimates[0].inclination_deg, 2.0, 0.05);
    const double expected_az = std::string(plugin) == "integral" ? 50 + 2.0 * std::tan(45.5 * kDeg) * std::sin(50 * kDeg) : 50;
    EXPECT_NEAR(wrap_deg_180(r.estimates[0].azimuth_deg - expected_az), 0, 1.0) << plugin;
  }
}

TEST(EstimatorBadInput, GapClosesTheWindowWithAReason) {
  for (const char* plugin : test::kRotatingPlugins) {
    auto samples = clean(60);
    samples.erase(samples.begin() + 500, samples.begin() + 700);  // 2 s missing
    const PluginRun r = run(plugin, samples);
    ASSERT_EQ(r.estimates.size(), 2u) << plugin;
    EXPECT_EQ(r.counters.at("gaps"), 1u);
    EXPECT_TRUE(r.estimates[0].partial_window);
    EXPECT_NE(r.estimates[0].reason.find("gap"), std::string::npos);
    for (const auto& e : r.estimates) {
      EXPECT_TRUE(e.valid) << e.reason;
      EXPECT_NEAR(e.inclination_deg, 2.0, 0.05);
    }
    EXPECT_NEAR(r.estimates[1].t_start, samples[500].t, 1e-12);
  }
}

TEST(EstimatorBadInput, ZeroFieldAndZeroSamplesAreInvalidNotNaN) {
  for (const char* plugin : test::kAllPlugins) {
    auto samples = clean(0);
    for (auto& s : samples) s.b.setZero();
    PluginRun r = run(plugin, samples);
    ASSERT_EQ(r.estimates.size(), 1u);
    EXPECT_FALSE(r.estimates[0].azimuth_valid) << plugin;
    EXPECT_FALSE(r.estimates[0].reason.empty());
    for (auto& s : samples) s.f.setZero();
    r = run(plugin, samples);
    ASSERT_EQ(r.estimates.size(), 1u);
    EXPECT_FALSE(r.estimates[0].valid) << plugin;
    EXPECT_FALSE(r.estimates[0].reason.empty());
  }
}

TEST(EstimatorBadInput, HugeValuesNeverProduceNaN) {
  for (const char* plugin : test::kAllPlugins) {
    auto samples = clean(60);
    for (std::size_t k = 0; k < samples.size(); k += 7) samples[k].f *= 1e300;
    for (std::size_t k = 0; k < samples.size(); k += 11) samples[k].b *= -1e300;
    run(plugin, samples);  // all_finite checked inside
  }
}

TEST(EstimatorBadInput, TooFewSamples) {
  for (const char* plugin : test::kAllPlugins) {
    auto samples = clean(0);
    samples.resize(5);
    const PluginRun r = run(plugin, samples);
    ASSERT_EQ(r.estimates.size(), 1u);
    EXPECT_FALSE(r.estimates[0].valid);
    EXPECT_NE(r.estimates[0].reason.find("too few samples"), std::string::npos);
  }
}

TEST(EstimatorBadInput, WindowTooShortForARevolution) {
  const auto samples = clean(60, 2, 50, 2);
  // integral needs whole revolutions: half a turn is refused with the reason.
  PluginRun r = run("integral", samples, {{"window", "0.5"}});
  ASSERT_EQ(r.estimates.size(), 4u);
  for (const auto& e : r.estimates) {
    EXPECT_FALSE(e.valid);
    EXPECT_NE(e.reason.find("too short for a revolution"), std::string::npos) << e.reason;
  }
  // compensated works on any arc and says that biases were not removed.
  r = run("compensated", samples, {{"window", "0.5"}});
  ASSERT_EQ(r.estimates.size(), 4u);
  for (const auto& e : r.estimates) {
    EXPECT_TRUE(e.valid) << e.reason;
    EXPECT_NE(e.reason.find("less than one revolution"), std::string::npos);
    EXPECT_NEAR(e.inclination_deg, 2.0, 0.1);
  }
}

TEST(EstimatorBadInput, NearVerticalReportsToolfaceAndAzimuthUndefined) {
  for (const char* plugin : test::kAllPlugins) {
    const auto samples = clean(std::string(plugin) == "static" ? 0 : 60, 0.0);
    const PluginRun r = run(plugin, samples);
    ASSERT_EQ(r.estimates.size(), 1u);
    EXPECT_TRUE(r.estimates[0].valid) << plugin << ": " << r.estimates[0].reason;
    EXPECT_LT(r.estimates[0].inclination_deg, 0.05);
  }
}

TEST(EstimatorWindows, BackToBackWindowsAndPartialLastWindow) {
  for (const char* plugin : test::kAllPlugins) {
    const auto samples = clean(std::string(plugin) == "static" ? 0 : 60);
    PluginRun r = run(plugin, samples, {{"window", "2"}});
    ASSERT_EQ(r.estimates.size(), 5u) << plugin;
    for (std::size_t i = 0; i < r.estimates.size(); ++i) {
      EXPECT_NEAR(r.estimates[i].t_start, 2.0 * i, 1e-9);
      EXPECT_EQ(r.estimates[i].samples_used > 0, true);
      EXPECT_FALSE(r.estimates[i].partial_window);
      EXPECT_TRUE(r.estimates[i].valid);
      EXPECT_EQ(r.estimates[i].estimator, plugin);
    }
    r = run(plugin, samples, {{"window", "3"}});
    ASSERT_EQ(r.estimates.size(), 4u);
    EXPECT_TRUE(r.estimates.back().partial_window);
    EXPECT_FALSE(r.estimates.front().partial_window);
  }
}

TEST(EstimatorWindows, ChunkingDoesNotChangeTheResult) {
  for (const char* plugin : test::kAllPlugins) {
    const auto samples = clean(std::string(plugin) == "static" ? 0 : 60);
    const PluginRun whole = run(plugin, samples, {{"window", "2.5"}});
    const PluginRun pieces = run(plugin, samples, {{"window", "2.5"}}, 37);
    ASSERT_EQ(whole.estimates.size(), pieces.estimates.size());
    for (std::size_t i = 0; i < whole.estimates.size(); ++i) {
      EXPECT_EQ(whole.estimates[i].azimuth_deg, pieces.estimates[i].azimuth_deg);
      EXPECT_EQ(whole.estimates[i].inclination_deg, pieces.estimates[i].inclination_deg);
    }
  }
}

TEST(EstimatorWindows, ConfigureResetsState) {
  auto e = estimator::load_estimator("compensated");
  e->configure({{"window", "0"}});
  std::vector<Estimate> out;
  const auto samples = clean(60);
  e->push(std::span(samples).first(300), out);
  e->configure({{"window", "0"}});
  EXPECT_TRUE(e->counters().empty());
  e->flush(out);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace plumb
