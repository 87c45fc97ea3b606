// The survey's options on the command line, the same for `plumb survey` (offline) and plumb-survey
// (live): azimuth reference and north corrections, reference field and QC tolerances, the error
// model's systematic terms, the vertical-section azimuth and tie-in, and the station detector.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "plumb/survey/navigator_tool_code.hpp"
#include "plumb/survey/station_detector.hpp"
#include "plumb/survey/survey.hpp"

namespace plumb::components {

struct SurveyCliOptions {
  std::string reference = "magnetic";
  std::optional<double> declination_deg, convergence_deg;
  double declination_sd_deg = 0;
  std::optional<double> gravity, total_field, dip;
  std::optional<double> latitude_deg;  // the gyro model's gyrocompass terms
  std::string reference_file;
  std::optional<double> tol_gravity, tol_field, tol_dip;
  std::vector<std::string> skip_checks;
  std::optional<double> section_azimuth_deg;  // none: the closure azimuth of the last station
  std::vector<double> tie_in;  // north,east,tvd
  double depth_sd_m = -1;      // < 0: what the depth input says
  double depth_scale_sd = 0;
  double axial_bias_sd_uT = 0;
  double axial_accel_bias_sd = 0;
  double still_tolerance_m = 0.02;
  double new_station_m = 0.1;
  double min_still_s = 5;
  std::string stop_station = "whole";
  std::string error_model = "auto";    // auto, plumb, a built-in tool code, or a tool code file
  std::vector<std::string> error_model_from;  // MD:MODEL, the survey program's later legs
  std::optional<double> pipe_length_m;
  std::string tally_file;  // per stop: joint_m (run in after it), correction_m (added to its depth)
  double start_md_m = 0;
};

void add_survey_options(CLI::App& app, SurveyCliOptions& o);

// Throws std::invalid_argument (a usage error) for options that cannot work, e.g. a true survey
// without declination, or no reference field for a check that is not skipped; std::runtime_error
// for an unreadable reference file.
// `estimator` names the estimator that measures the stations. The strapdown navigator's survey is
// no magnetic survey: `--error-model auto` gives it the ISCWSA gyro model of the navigator's own
// figures (survey::iscwsa::navigator_tool_code) from `navigator`, its parameters with their values
// in use, or plumb's own propagation when they are not known (nullptr: the caller says so); ISCWSA's
// MWD model elsewhere. A gyro model on the navigator's stations counts each station's own sigma by
// its excess over the model's only (survey::SurveyOptions::station_sigma_beyond_model). The
// navigator's latitude serves a gyrocompass's terms when --latitude is not given.
survey::SurveyOptions make_survey_options(const SurveyCliOptions& o, const std::string& estimator = "",
                                          const survey::iscwsa::NavigatorParameters* navigator = nullptr);
// The plugin whose stations are the strapdown navigator's.
inline constexpr const char* kNavigatorPlugin = "strapdown";
// Throws std::invalid_argument for bad values, std::runtime_error for an unreadable tally file.
survey::DetectorOptions make_detector_options(const SurveyCliOptions& o);

}  // namespace plumb::components
