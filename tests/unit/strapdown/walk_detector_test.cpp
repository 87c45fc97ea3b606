// A stream without magnetometer readings (no bx,by,bz columns, a tool without magnetometers) needs
// no use_magnetometer=0: still_detector=auto sees that the samples carry no field and takes the
// GLRT, which does not lean on |B|. Before, auto kept the magnitude test for such files, and a real
// foot-mounted recording (tests/data/walks) found 3 still periods in 21 s of walking instead of 20.
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/sim/walk.hpp"
#include "plumb/strapdown/navigator.hpp"
#include "plumb/strapdown/parameters.hpp"

namespace plumb::strapdown {
namespace {

struct Result {
  std::map<std::string, std::uint64_t> counters;
  std::array<double, 3> end{};
};

Result navigate(const std::vector<Sample>& samples, estimator::Parameters params) {
  Navigator nav(parse_parameters(params));
  std::vector<Estimate> rows;
  for (const Sample& s : samples) nav.push(s, rows);
  nav.flush(rows);
  return {nav.counters(), rows.back().navigation->position_m};
}

TEST(WalkDetector, AutoTakesTheGlrtWhenSamplesCarryNoField) {
  auto scenario = sim::WalkScenario::loop_25m();
  scenario.magnetometer = false;
  const std::vector<Sample> samples = sim::WalkSimulator(scenario).run();
  const estimator::Parameters params{{"latitude_deg", "35"}, {"gravity", "9.80665"}, {"imu_grade", "mems"},
                                     {"min_still_s", "0.05"}, {"initial_azimuth_deg", "0"}, {"align_s", "8"}};
  auto with = [&](const char* detector) {
    estimator::Parameters p = params;
    p["still_detector"] = detector;
    return navigate(samples, p);
  };
  const Result automatic = navigate(samples, params), glrt = with("glrt"), magnitude = with("magnitude");
  EXPECT_EQ(automatic.counters.at("zero_velocity_updates"), glrt.counters.at("zero_velocity_updates"));
  EXPECT_EQ(automatic.end, glrt.end);
  // The two detectors differ on this walk, so the equality above says which one auto took.
  EXPECT_NE(glrt.counters.at("zero_velocity_updates"), magnitude.counters.at("zero_velocity_updates"));
}

// A foot or a hand-carried sensor does not move along its own axis; with the
// drilling tool's lateral-velocity update off, none is applied and the walk still closes.
TEST(WalkDetector, LateralVelocityUpdateCanBeTurnedOff) {
  auto scenario = sim::WalkScenario::loop_25m();
  scenario.magnetometer = false;
  const std::vector<Sample> samples = sim::WalkSimulator(scenario).run();
  const Result r = navigate(samples, {{"latitude_deg", "35"}, {"gravity", "9.80665"}, {"imu_grade", "mems"},
                                      {"min_still_s", "0.05"}, {"initial_azimuth_deg", "0"}, {"align_s", "8"},
                                      {"lateral_velocity_update", "0"}});
  EXPECT_EQ(r.counters.count("lateral_velocity_updates") ? r.counters.at("lateral_velocity_updates") : 0u, 0u);
  EXPECT_LT(std::hypot(r.end[0], r.end[1], r.end[2]), 0.003 * 25.0);
}

// A drilling tool's filter runs stop_lag_s behind its stillness detector and drops stops shorter
// than that; a foot's stances last a fraction of a second, so a foot's filter does not wait.
TEST(WalkDetector, AFootsStancesDoNotWaitForTheStopLag) {
  auto scenario = sim::WalkScenario::loop_25m();
  scenario.magnetometer = false;
  const std::vector<Sample> samples = sim::WalkSimulator(scenario).run();
  estimator::Parameters params{{"latitude_deg", "35"}, {"gravity", "9.80665"}, {"imu_grade", "mems"},
                               {"min_still_s", "0.05"}, {"initial_azimuth_deg", "0"}, {"align_s", "8"},
                               {"lateral_velocity_update", "0"}, {"stop_lag_s", "2"}};
  const Result lag_asked = navigate(samples, params);
  params["stop_lag_s"] = "0";
  const Result no_lag = navigate(samples, params);
  EXPECT_GT(no_lag.counters.at("still_periods"), 15u);
  EXPECT_EQ(lag_asked.counters.at("still_periods"), no_lag.counters.at("still_periods"));
  EXPECT_EQ(lag_asked.end, no_lag.end);
}

}  // namespace
}  // namespace plumb::strapdown
