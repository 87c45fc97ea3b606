// The inputs of `plumb survey`: an attitude CSV (docs/conventions.md) with a depth log, or a station
// list; each row checked, a bad one an error naming file, line and column.
#pragma once

#include <string>
#include <vector>

#include "plumb/core/estimate.hpp"
#include "plumb/survey/station_detector.hpp"
#include "plumb/survey/survey.hpp"

namespace plumb::survey {

// Attitude CSV: t (window end), inclination_deg, azimuth_deg, valid; optional inclination_sd_deg,
// azimuth_sd_deg, dip_deg, total_g, total_b, azimuth_valid, rpm, estimator. Each window starts
// `window_s` before its t (<= 0: the median spacing of the rows).
std::vector<Estimate> read_attitude_csv(const std::string& path, double window_s);

// Depth log: t, depth_m, optional depth_sd_m; times increasing.
std::vector<DepthReport> read_depth_csv(const std::string& path);

// Station list: md_m, inclination_deg, azimuth_deg (magnetic); optional md_sd_m,
// inclination_sd_deg, azimuth_sd_deg, total_g_mps2, total_b_uT, dip_deg, t.
std::vector<Station> read_station_csv(const std::string& path);

}  // namespace plumb::survey
