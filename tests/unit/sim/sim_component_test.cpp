// plumb-sim's command line becomes the intended scenario, its pacing text is parsed strictly,
// and its CSV output reads back (through the project's CSV reader) as the simulator's samples.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "csv_sink.hpp"
#include "pacing.hpp"
#include "plumb/csv/files.hpp"
#include "scenario_options.hpp"

namespace plumb::sim_component {
namespace {

sim::Scenario parse(std::vector<std::string> args) {
  CLI::App app;
  ScenarioOptions options;
  add_scenario_options(app, options);
  std::reverse(args.begin(), args.end());  // CLI11 takes the vector reversed
  app.parse(args);
  return make_scenario(app, options);
}

TEST(PlumbSimOptions, ReferencePresetIsThePapersCase) {
  const sim::Scenario s = parse({"--preset", "reference", "--inclination", "0.5", "--azimuth", "90", "--rpm", "120"});
  const sim::Scenario r = sim::Scenario::reference(0.5, 90, 120, 20);
  EXPECT_EQ(s.g, 10.0);
  EXPECT_EQ(s.total_b, 48.4);
  EXPECT_EQ(s.dip_deg, 45.5);
  EXPECT_EQ(s.sample_rate_hz, 100.0);
  EXPECT_EQ(s.duration_s, 10.0);
  EXPECT_EQ(s.rotation.rpm, 120.0);
  EXPECT_EQ(s.sigma_accel(), r.sigma_accel());
  EXPECT_EQ(s.sigma_mag(), r.sigma_mag());
}

TEST(PlumbSimOptions, ExplicitOptionsOverrideThePreset) {
  const sim::Scenario s = parse({"--preset", "reference", "--g", "9.81", "--snr-accel", "10", "--sigma-mag", "0.5",
                                 "--count", "250", "--rate-hz", "50", "--profile", "stickslip:60:2"});
  EXPECT_EQ(s.g, 9.81);
  EXPECT_EQ(*s.noise.snr_accel_db, 10.0);
  EXPECT_EQ(s.sigma_mag(), 0.5);
  EXPECT_EQ(sim::PlatformSimulator(s).sample_count(), 250u);
  EXPECT_EQ(s.rotation.kind, sim::ProfileKind::StickSlip);
}

TEST(PlumbSimOptions, SensorErrorsTemperatureAndVibration) {
  const sim::Scenario s = parse({"--accel-bias", "0.1,-0.2,0.3", "--mag-scale", "0.01,0,0", "--temp", "20:80",
                                 "--vibration", "0.4", "--shock-rate", "1", "--shock-peak", "30", "--no-gyro",
                                 "--tool-id", "t7", "--seed", "9"});
  EXPECT_EQ(s.accel_errors.bias, Eigen::Vector3d(0.1, -0.2, 0.3));
  EXPECT_EQ(s.mag_errors.scale, Eigen::Vector3d(0.01, 0, 0));
  EXPECT_EQ(s.temp_start_c, 20.0);
  EXPECT_EQ(s.temp_end_c, 80.0);
  EXPECT_EQ(s.vibration.lateral_rms, 0.4);
  EXPECT_EQ(s.vibration.shock_peak, 30.0);
  EXPECT_FALSE(s.with_gyro);
  EXPECT_EQ(s.tool_id, "t7");
  EXPECT_EQ(s.seed, 9u);
  EXPECT_EQ(parse({"--temp", "60"}).temp_end_c, 60.0);
  EXPECT_FALSE(parse({}).noise.snr_accel_db.has_value());  // no noise unless asked for
}

TEST(PlumbSimOptions, BadValuesAreRejectedNamingTheOption) {
  for (const auto& args : std::vector<std::vector<std::string>>{{"--accel-bias", "1,2"},
                                                                {"--mag-bias", "1,x,2"},
                                                                {"--temp", "1:2:3"},
                                                                {"--temp", "hot"},
                                                                {"--count", "0"},
                                                                {"--profile", "stopgo:60"},
                                                                {"--tool-id", std::string(40, 'a')}}) {
    try {
      parse(args);
      ADD_FAILURE() << "accepted " << args[0] << " " << args[1];
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      const bool names_it = what.find(args[0]) != std::string::npos || what.find("profile") != std::string::npos;
      EXPECT_TRUE(names_it) << what;
    }
  }
}

TEST(PlumbSimCsv, FilesReadBackAsTheSimulatedSamples) {
  const auto dir = std::filesystem::temp_directory_path() / ("plumb_sim_csv_test_" + std::to_string(::getpid()));
  sim::Scenario sc = sim::Scenario::reference(2, 40, 60, 10, 3);
  sc.duration_s = 1;
  sc.temp_start_c = 30;
  sc.temp_end_c = 40;
  std::vector<TruthSample> truth;
  const auto samples = sim::PlatformSimulator(sc).run(&truth);
  {
    CsvSink sink(dir.string(), true);
    for (std::size_t k = 0; k < samples.size(); k += 7) {
      const std::size_t end = std::min(samples.size(), k + 7);
      sink.write({samples.begin() + k, samples.begin() + end}, {truth.begin() + k, truth.begin() + end});
    }
    sink.finish(false);
  }
  const auto back = csv::read_sensor_file((dir / "sensor.csv").string());
  const auto truth_back = csv::read_truth_file((dir / "truth.csv").string());
  ASSERT_EQ(back.size(), samples.size());
  ASSERT_EQ(truth_back.size(), truth.size());
  // The writer keeps 10 significant digits.
  auto close = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); };
  for (std::size_t k = 0; k < samples.size(); ++k) {
    EXPECT_EQ(back[k].seq, samples[k].seq);
    EXPECT_TRUE(close(back[k].t, samples[k].t));
    for (int i = 0; i < 3; ++i) {
      EXPECT_TRUE(close(back[k].f[i], samples[k].f[i]));
      EXPECT_TRUE(close(back[k].b[i], samples[k].b[i]));
      EXPECT_TRUE(close(back[k].w[i], samples[k].w[i]));
    }
    EXPECT_TRUE(close(back[k].temp_c, samples[k].temp_c));
    EXPECT_TRUE(close(truth_back[k].toolface_deg, truth[k].toolface_deg));
    EXPECT_TRUE(close(truth_back[k].azimuth_deg, 40));
  }
  std::filesystem::remove_all(dir);
}

TEST(PlumbSimDrillingOptions, ScenarioGradeAndOverrides) {
  CLI::App app;
  ScenarioOptions options;
  add_scenario_options(app, options);
  std::vector<std::string> args{"--scenario", "drilling", "--grade", "mems", "--rate-hz", "10", "--seed", "4",
                                "--latitude", "50", "--sigma-mag", "0.2", "--mag-disturbance", "1:1:0.5",
                                "--mag-disturbance", "3:-2:0", "--depth-noise", "0.01", "--depth-step", "0.05",
                                "--gyro-bias", "1e-5,0,-1e-5", "--gyro-range", "400", "--inclination", "88",
                                "--circulation-temp", "55:95"};
  std::reverse(args.begin(), args.end());
  app.parse(args);
  ASSERT_TRUE(is_drilling(options));
  const sim::DrillingScenario s = make_drilling_scenario(app, options);
  EXPECT_EQ(s.grade.name, "mems");
  EXPECT_EQ(s.grade.gyro_range_deg_s, 400.0);
  EXPECT_EQ(s.sample_rate_hz, 10.0);
  EXPECT_EQ(s.seed, 4u);
  EXPECT_EQ(s.latitude_deg, 50.0);
  EXPECT_EQ(s.magnetometer.sigma_uT, 0.2);
  ASSERT_EQ(s.magnetometer.disturbances.size(), 2u);
  EXPECT_EQ(s.magnetometer.disturbances[1].stop_index, 3u);
  EXPECT_EQ(s.magnetometer.disturbances[1].delta_total_uT, -2.0);
  EXPECT_EQ(s.depth.sigma_m, 0.01);
  EXPECT_EQ(s.depth.quantum_m, 0.05);
  EXPECT_EQ(*s.gyro_bias, Eigen::Vector3d(1e-5, 0, -1e-5));
  EXPECT_EQ(s.plan.inclination_deg, 88.0);
  EXPECT_TRUE(s.temperature.enabled);
  EXPECT_EQ(s.temperature.circulating_c, 55.0);
  EXPECT_EQ(s.temperature.start_c, 55.0);
  EXPECT_EQ(s.temperature.formation_c, 95.0);
  EXPECT_FALSE(sim::DrillingScenario().temperature.enabled);
  EXPECT_EQ(s.plan.segments.size(), sim::DrillingScenario::reference(s.grade).plan.segments.size());
  EXPECT_EQ(s.duration_s(), 960.0);
}

TEST(PlumbSimDrillingOptions, OptionsOfTheOtherKindAreRefusedByName) {
  struct Case {
    std::vector<std::string> args;
    std::string named;
  };
  for (const auto& c : std::vector<Case>{{{"--scenario", "drilling", "--rpm", "60"}, "--rpm"},
                                         {{"--scenario", "drilling", "--duration", "5"}, "--duration"},
                                         {{"--scenario", "drilling-survey", "--temp", "30"}, "--temp"},
                                         {{"--scenario", "drilling", "--grade", "cheap"}, "--grade"},
                                         {{"--scenario", "drilling", "--mag-disturbance", "9:1:0"}, "stop 9"},
                                         {{"--scenario", "drilling", "--mag-disturbance", "1:1"}, "--mag-disturbance"},
                                         {{"--scenario", "drilling", "--gyro-range", "0"}, "--gyro-range"},
                                         {{"--scenario", "drilling", "--circulation-temp", "60"}, "--circulation-temp"},
                                         {{"--circulation-temp", "60:90"}, "--circulation-temp"},
                                         {{"--grade", "mems"}, "--grade"},
                                         {{"--no-mag"}, "--no-mag"}}) {
    CLI::App app;
    ScenarioOptions options;
    add_scenario_options(app, options);
    auto reversed = c.args;
    std::reverse(reversed.begin(), reversed.end());
    app.parse(reversed);
    try {
      if (is_drilling(options))
        make_drilling_scenario(app, options);
      else
        make_scenario(app, options);
      ADD_FAILURE() << "accepted " << c.named;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(c.named), std::string::npos) << e.what();
    }
  }
}

TEST(PlumbSimCsv, DrillingRunWritesDepthAndPosition) {
  const auto dir = std::filesystem::temp_directory_path() / ("plumb_sim_drill_csv_" + std::to_string(::getpid()));
  sim::DrillingScenario sc = sim::DrillingScenario::survey_stop_and_go(sim::ImuGrade::tactical(), 10, 2);
  std::vector<TruthSample> truth;
  const auto samples = sim::DrillingSimulator(sc).run(&truth);
  {
    CsvSink sink(dir.string(), CsvColumns{true, false, true, true});
    EXPECT_TRUE(sink.carries_depth());
    sink.write(samples, truth);
    sink.finish(false);
  }
  const auto back = csv::read_sensor_file((dir / "sensor.csv").string());
  const auto truth_back = csv::read_truth_file((dir / "truth.csv").string());
  ASSERT_EQ(back.size(), samples.size());
  ASSERT_EQ(truth_back.size(), truth.size());
  auto close = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); };
  for (std::size_t k = 0; k < samples.size(); ++k) {
    ASSERT_TRUE(back[k].flags & flags::kHasGyro);
    ASSERT_TRUE(back[k].flags & flags::kHasDepth);
    ASSERT_FALSE(back[k].flags & flags::kHasTemperature);
    EXPECT_TRUE(close(back[k].depth_m, samples[k].depth_m));
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(close(back[k].w[i], samples[k].w[i]));
    ASSERT_TRUE(truth_back[k].has_position);
    EXPECT_TRUE(close(truth_back[k].north_m, truth[k].north_m));
    EXPECT_TRUE(close(truth_back[k].down_m, truth[k].down_m));
    EXPECT_TRUE(close(truth_back[k].vd_mps, truth[k].vd_mps));
    EXPECT_TRUE(close(truth_back[k].depth_m, truth[k].depth_m));
  }
  EXPECT_NEAR(truth_back.back().depth_m, 9.0, 1e-9);
  std::filesystem::remove_all(dir);
}

TEST(PlumbSimCsv, UnwritableDirectoryIsAClearError) {
  EXPECT_THROW(CsvSink("/proc/plumb-sim-cannot-be-here", true), std::runtime_error);
}

}  // namespace
}  // namespace plumb::sim_component
