// --error-model on the command line (components::make_survey_options): what `auto` gives each
// estimator's stations, and when a station's own sigma counts by its excess over a gyro model's.
#include "plumb/components/survey_options.hpp"

#include <gtest/gtest.h>

#include "plumb/strapdown/parameters.hpp"

namespace plumb::components {
namespace {

survey::iscwsa::NavigatorParameters navigator_in_use(const std::string& key = "", const std::string& value = "") {
  survey::iscwsa::NavigatorParameters p;
  for (const auto& spec : strapdown::parameter_specs()) p[spec.name] = spec.default_value;
  if (!key.empty()) p.at(key) = value;
  return p;
}

SurveyCliOptions cli(const std::string& error_model) {
  SurveyCliOptions o;
  o.error_model = error_model;
  o.skip_checks = {"gravity", "field", "dip"};
  return o;
}

TEST(SurveyOptions, AutoIsTheNavigatorsOwnGyroModelOnItsStations) {
  const auto navigator = navigator_in_use();
  const survey::SurveyOptions s = make_survey_options(cli("auto"), kNavigatorPlugin, &navigator);
  ASSERT_TRUE(s.tool_code.has_value());
  EXPECT_EQ(s.tool_code->name, "GYRO:navigator (tactical; magnetic az 0.689 deg)");
  EXPECT_TRUE(s.station_sigma_beyond_model);
  // Without its parameters: plumb's own terms (the caller says why).
  const survey::SurveyOptions unknown = make_survey_options(cli("auto"), kNavigatorPlugin);
  EXPECT_FALSE(unknown.tool_code.has_value());
  EXPECT_FALSE(unknown.station_sigma_beyond_model);
  // Every other estimator's stations: the MWD model, their sigma counted in full.
  const survey::SurveyOptions windowed = make_survey_options(cli("auto"), "compensated", &navigator);
  ASSERT_TRUE(windowed.tool_code.has_value());
  EXPECT_EQ(windowed.tool_code->name.rfind("MWD", 0), 0u);
  EXPECT_FALSE(windowed.station_sigma_beyond_model);
}

TEST(SurveyOptions, AnyGyroModelOnTheNavigatorsStationsCountsTheirSigmaByItsExcess) {
  EXPECT_TRUE(make_survey_options(cli("GYRO:tactical"), kNavigatorPlugin).station_sigma_beyond_model);
  EXPECT_FALSE(make_survey_options(cli("GYRO:tactical"), "compensated").station_sigma_beyond_model);
  EXPECT_FALSE(make_survey_options(cli("MWD"), kNavigatorPlugin).station_sigma_beyond_model);
  EXPECT_FALSE(make_survey_options(cli("plumb"), kNavigatorPlugin).tool_code.has_value());
}

TEST(SurveyOptions, AGyrocompassingNavigatorLendsItsLatitude) {
  const auto navigator = navigator_in_use("gyrocompass", "1");
  const survey::SurveyOptions s = make_survey_options(cli("auto"), kNavigatorPlugin, &navigator);
  EXPECT_EQ(s.latitude_deg, 45);  // the navigator's default latitude_deg
  EXPECT_NO_THROW(survey::Survey{s});
  SurveyCliOptions given = cli("auto");
  given.latitude_deg = 60;
  EXPECT_EQ(make_survey_options(given, kNavigatorPlugin, &navigator).latitude_deg, 60);
}

}  // namespace
}  // namespace plumb::components
