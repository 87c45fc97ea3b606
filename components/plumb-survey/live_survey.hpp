// plumb-survey's loop: attitude and depth topics in, stations detected, quality-checked, placed
// by minimum curvature, written to the survey file (fsync'ed) and only then published.
#pragma once

#include <optional>
#include <string>

#include "plumb/components/clearance_options.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/components/survey_options.hpp"

namespace plumb::survey_component {

struct LiveOptions {
  components::TransportOptions transport;
  components::SurveyCliOptions survey;
  std::string estimator = "compensated";  // reads plumb/attitude/<estimator>: fits a turning or standing tool
  std::string attitude_topic;        // overrides the estimator's topic
  // The host that runs the estimator (its plumb-estimator --name; empty: this computer's host name),
  // asked for the navigator's parameters when `--error-model auto` surveys the navigator's stations,
  // waiting this long for its answer.
  std::string estimator_host;
  double estimator_wait_s = 10;
  std::string tool_id;               // the tool surveyed: its attitude and depth; names plumb/survey/<tool>
  std::string file;                  // the survey file (required)
  int count = 0;                     // exit once the survey holds this many stations (0: run until stopped)
  double timeout_s = 0;              // fail if --count is not reached in time
  double linger_s = 1;
  bool quiet = false;
  // The depth's clock against the sensors' (docs/wits.md, "Clocks"): given, or estimated from the
  // stops seen on the depth and on sensor_topic.
  std::optional<double> depth_clock_offset_s;
  std::optional<double> depth_clock_drift_ppm;
  std::string sensor_topic = "plumb/sensor/calibrated";
  // Anti-collision: offset wells, each new station against every one, on plumb/clearance.
  components::ClearanceCliOptions clearance;
  std::string offset_error_model = "MWD";  // how a station-list offset well is surveyed
};

int run_live_survey(const LiveOptions& options);

}  // namespace plumb::survey_component
