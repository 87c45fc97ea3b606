// plumb-sim --scenario walk: the command line becomes the intended walk, options that a walk would
// ignore are refused by name (and walk options elsewhere), and its CSV carries gyros and positions.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "csv_sink.hpp"
#include "plumb/csv/files.hpp"
#include "scenario_options.hpp"

namespace plumb::sim_component {
namespace {

struct Parsed {
  CLI::App app;
  ScenarioOptions options;
  explicit Parsed(std::vector<std::string> args) {
    add_scenario_options(app, options);
    std::reverse(args.begin(), args.end());  // CLI11 takes the vector reversed
    app.parse(args);
  }
};

TEST(PlumbSimWalkOptions, NamedLoopsAndOverrides) {
  Parsed p25({"--scenario", "walk"});
  ASSERT_TRUE(is_walk(p25.options));
  EXPECT_FALSE(is_drilling(p25.options));
  const sim::WalkScenario s25 = make_walk_scenario(p25.app, p25.options);
  EXPECT_EQ(s25.tool_id, "walk-25m");
  EXPECT_EQ(s25.grade.name, "mems");
  EXPECT_EQ(s25.sample_rate_hz, 400.0);
  EXPECT_NEAR(sim::WalkPath(s25).horizontal_length_m(), 25.0, 1e-9);

  Parsed p60({"--scenario", "walk", "--walk-length", "60", "--grade", "tactical", "--rate-hz", "200", "--seed", "7",
              "--azimuth", "30", "--latitude", "60", "--no-mag", "--gyro-bias", "1e-4,0,0", "--gyro-range", "1000"});
  const sim::WalkScenario s60 = make_walk_scenario(p60.app, p60.options);
  EXPECT_EQ(s60.tool_id, "walk-60m");
  EXPECT_EQ(s60.grade.name, "tactical");
  EXPECT_EQ(s60.grade.gyro_range_deg_s, 1000.0);
  EXPECT_EQ(s60.sample_rate_hz, 200.0);
  EXPECT_EQ(s60.seed, 7u);
  EXPECT_EQ(s60.heading_deg, 30.0);
  EXPECT_EQ(s60.latitude_deg, 60.0);
  EXPECT_FALSE(s60.magnetometer);
  EXPECT_EQ(*s60.gyro_bias, Eigen::Vector3d(1e-4, 0, 0));
  EXPECT_EQ(s60.legs.size(), sim::WalkScenario::loop_60m().legs.size());

  Parsed flat({"--scenario", "walk", "--walk-length", "60", "--walk-climb", "0"});
  EXPECT_EQ(make_walk_scenario(flat.app, flat.options).legs.size(), 4u);
}

TEST(PlumbSimWalkOptions, OptionsOfTheOtherKindsAreRefusedByName) {
  struct Case {
    std::vector<std::string> args;
    std::string named;
  };
  for (const auto& c : std::vector<Case>{{{"--scenario", "walk", "--duration", "5"}, "--duration"},
                                         {{"--scenario", "walk", "--inclination", "10"}, "--inclination"},
                                         {{"--scenario", "walk", "--vibration", "1"}, "--vibration"},
                                         {{"--scenario", "walk", "--no-depth"}, "--no-depth"},
                                         {{"--scenario", "walk", "--mag-disturbance", "0:1:0"}, "--mag-disturbance"},
                                         {{"--scenario", "walk", "--walk-length", "0"}, "--walk-length"},
                                         {{"--scenario", "walk", "--walk-length", "10", "--walk-climb", "5"}, "fit"},
                                         {{"--scenario", "walk", "--grade", "cheap"}, "--grade"},
                                         {{"--scenario", "drilling", "--walk-length", "60"}, "--walk-length"},
                                         {{"--walk-climb", "3"}, "--walk-climb"}}) {
    Parsed p(c.args);
    try {
      if (is_walk(p.options))
        make_walk_scenario(p.app, p.options);
      else if (is_drilling(p.options))
        make_drilling_scenario(p.app, p.options);
      else
        make_scenario(p.app, p.options);
      ADD_FAILURE() << "accepted " << c.named;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(c.named), std::string::npos) << e.what();
    }
  }
}

TEST(PlumbSimCsv, WalkWritesGyrosAndPosition) {
  const auto dir = std::filesystem::temp_directory_path() / ("plumb_sim_walk_csv_" + std::to_string(::getpid()));
  const sim::WalkScenario sc = sim::WalkScenario::loop_25m(sim::ImuGrade::mems(), 50, 3);
  std::vector<TruthSample> truth;
  const auto samples = sim::WalkSimulator(sc).run(&truth);
  {
    CsvSink sink(dir.string(), CsvColumns{true, false, false, true});
    sink.write(samples, truth);
    sink.finish(false);
  }
  const auto back = csv::read_sensor_file((dir / "sensor.csv").string());
  const auto truth_back = csv::read_truth_file((dir / "truth.csv").string());
  ASSERT_EQ(back.size(), samples.size());
  ASSERT_EQ(truth_back.size(), truth.size());
  auto close = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); };
  double farthest = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    ASSERT_TRUE(back[k].flags & flags::kHasGyro);
    ASSERT_FALSE(back[k].flags & flags::kHasDepth);
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(close(back[k].w[i], samples[k].w[i]));
    ASSERT_TRUE(truth_back[k].has_position);
    EXPECT_TRUE(close(truth_back[k].east_m, truth[k].east_m));
    EXPECT_TRUE(close(truth_back[k].ve_mps, truth[k].ve_mps));
    farthest = std::max(farthest, std::hypot(truth_back[k].north_m, truth_back[k].east_m));
  }
  EXPECT_GT(farthest, 9.0);  // the far corner of the 8.3 x 4.2 m rectangle
  EXPECT_LT(std::hypot(truth_back.back().north_m, truth_back.back().east_m), 1e-9);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace plumb::sim_component
