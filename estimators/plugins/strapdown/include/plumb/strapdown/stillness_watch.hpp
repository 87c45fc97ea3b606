// The navigator's stillness watch: the stillness detector with the limits it takes from the noise
// (stated, or read off the data before alignment: noise_floor.hpp), the depth tolerance, the biases
// and allowances it takes from the filter once aligned, and the notices of a run that never aligns
// or finds no stop (never silent: which test fails, by how much, and the parameter to change).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/filter_state.hpp"
#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/navigator_config.hpp"
#include "plumb/strapdown/noise_floor.hpp"
#include "plumb/strapdown/ring_queue.hpp"
#include "plumb/strapdown/stillness.hpp"

namespace plumb::strapdown {

class StillnessWatch {
 public:
  void reset(const NavigatorConfig& config);
  // still_detector=auto: the magnitude test leans on |B|. A stream whose first sample has no field
  // gets the GLRT, as use_magnetometer=0 does.
  void use_glrt_without_field();
  // A gap: the window and any period are forgotten.
  void forget() { detector_.reset(); }
  // The detector's noise at the nominal sample interval: measured where the user stated none.
  void refresh_noise(double dt);

  // One reading before alignment (b0: the reference |B|, when known): the noise floor, the notice
  // of a run that cannot align, and the detector's verdict.
  StillnessState before_alignment(const InputReading& in, std::optional<double> b0);
  // One reading once aligned: the detector with the filter's biases and earth rate taken out.
  StillnessState aligned(const InputReading& in, const FilterState& filter, std::optional<double> b0);
  // At alignment: the filter takes the measured noise where none was stated and it exceeds the
  // preset (and the log says which noise set the limits); then the detector's long means restart.
  void adopt_measured_noise(double dt, ProcessNoise& noise);
  // lagging: the filter runs behind the detector (stillness_lag.hpp), which then carries the tool's
  // attitude forward itself for the earth rate; without a lag the filter's is current.
  void on_aligned(double t, bool lagging);
  // Once aligned, at the filter's epochs (they change with the filter only; t: the filter's time,
  // which may be behind the detector's): what the detector does not know of w_expected, the biases
  // it takes out, and the attitude it takes the earth rate out with.
  void refresh_allowances(const FilterState& filter, double t);
  // Aligned: a run without a stop for no_stop_notice_s says so once.
  void watch_for_stops(double t, bool still);

  bool still() const { return detector_.still(); }
  StillnessConfig::Mode mode() const { return detector_.config().mode; }
  // The filter's depth noise: stated, or the larger of the default and the floor (which may grow
  // after alignment, when the reports' spread about their trend shows a swell).
  double depth_sd() const { return depth_sd_; }
  // The depth test's limit: the largest 1 s depth change of a tool it calls still (m).
  double depth_tolerance() const { return detector_.config().depth_tol_m; }
  // Whether any reading before alignment carried a depth report.
  bool depth_seen() const { return depth_seen_; }
  // The short reason of a row that cannot align, once the notice said the rest; empty before.
  std::string not_aligned_reason() const;
  std::vector<std::string> take_notices() { return std::exchange(notices_, {}); }

 private:
  StillnessInput raw_input(const InputReading& in, std::optional<double> b0) const;
  StillnessInput aligned_input(const InputReading& in, const FilterState& filter, std::optional<double> b0) const;
  void field_deviation(const InputReading& in, std::optional<double> b0, StillnessInput& si) const;
  void refresh_depth_tolerance();
  void turn_with(const InputReading& in);
  void follow_filter(const FilterState& filter, double t);
  void watch_before_alignment(const InputReading& in);
  void adopt_noise_floor();
  void adopt_depth_floor();
  bool noise_known() const;
  std::string failing_test_text() const;

  NavigatorConfig config_;
  StillnessDetector detector_;
  bool aligned_ = false;
  bool lagging_ = false;
  double aligned_gyro_tol_ = 0;  // the detector's extra gyro tolerance once aligned (refresh_allowances)
  // The biases the detector takes out once aligned: the filter's, within 3 sigma of the figures.
  Eigen::Vector3d detector_ba_ = Eigen::Vector3d::Zero(), detector_bg_ = Eigen::Vector3d::Zero();
  // The tool's attitude since alignment, in a frame of its own (tool0), turned by each aligned
  // reading, with its history back to the filter's time; the earth rate in tool0 as the filter's
  // attitude at its time gives it.
  Eigen::Quaterniond tool_attitude_ = Eigen::Quaterniond::Identity();
  RingQueue<std::pair<double, Eigen::Quaterniond>> turns_;
  Eigen::Vector3d earth_rate_tool0_ = Eigen::Vector3d::Zero();
  NoiseFloor noise_floor_;
  std::size_t floor_blocks_used_ = 0;
  // Per-sample noise read off the data, for what the user did not state (the magnitude detector).
  std::optional<double> measured_sigma_a_, measured_sigma_w_, measured_depth_sd_;
  double depth_sd_ = 0.01;
  bool depth_raised_notice_given_ = false;
  std::optional<double> first_t_;
  bool depth_seen_ = false;
  StillnessTally tally_;  // what kept the detector from a still period since alignment or the last stop
  bool align_notice_given_ = false, stop_notice_given_ = false;
  double last_still_t_ = 0;
  std::vector<std::string> notices_;
};

}  // namespace plumb::strapdown
