// The navigator's measurement updates at its filter epochs: at a stop the zero velocity, the
// gyros' zero rate (and tilt), the magnetic heading (gated by the field the alignment learnt),
// and a pipe tally's distance at a connection; at a stop's end, what a late-seen end may have
// hidden; while moving, the lateral velocity of a tool that moves along its axis (its noise matched
// to the innovations, the excess carried as process noise); and the measured depth, whenever a
// report is due.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "plumb/strapdown/alignment.hpp"
#include "plumb/strapdown/filter_state.hpp"
#include "plumb/strapdown/heave_filter.hpp"
#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/navigator_config.hpp"
#include "plumb/strapdown/stillness.hpp"

namespace plumb::strapdown {

// The σ of a still stretch's mean specific force (a tilt measurement): the scatter seen, never
// below the sensor's white noise or the floor.
double mean_force_sd(const StillStats& stats, double accel_vrw, double dt);

class StopUpdates {
 public:
  void reset(const NavigatorConfig& config);
  // A reading's depth report (prev_had_depth: whether the reading before carried one; still: the
  // stillness decision the filter takes for it; depth_sd: the depth's noise, stated or measured).
  // Before the alignment only the swell's models take it (the alignment's depth is their trend).
  void take_depth(double t, double depth, bool prev_had_depth, const FilterState& filter, bool still, double depth_sd);
  // What the log should say once: a swell found on the depth reports.
  std::vector<std::string> take_notices() { return std::exchange(notices_, {}); }
  // An aligned reading's stillness: a stop that starts restarts the stop's means.
  void follow(const InputReading& in, const StillnessState& still, Counters& counters);
  // At alignment: the alignment's own means as the filter's first measurements (they shape P:
  // tilt against the accelerometer biases, heading against the gyro biases, as the data warrant).
  void at_alignment(FilterState& filter, const StillStats& stats, double sd_mean_f, double dt, bool use_mag,
                    const FieldReference& field, std::optional<double> depth, Counters& counters);
  // How far the filter runs behind the stillness detector (stillness_lag.hpp), set at alignment.
  void set_stop_lag(double lag_s) { stop_lag_s_ = lag_s; }
  // At a filter epoch t, after the prediction to it (dt_nominal: the sample interval, 0 when not
  // known yet; depth_sd: the depth's noise, stated or measured; depth_tolerance_m: the stillness
  // detector's depth limit).
  void at_epoch(FilterState& filter, const FilterState::Prediction& prediction, const StillnessState& still, double t,
                double dt_nominal, double depth_sd, double depth_tolerance_m, bool use_mag,
                const FieldReference& field, Counters& counters);

  // The process noise of the next filter epoch: the figures' and, while moving, the lateral
  // velocity's measured excess beyond what a tool's lateral velocity can be.
  ProcessNoise process_noise(const ProcessNoise& noise, const StillnessState& still, bool drilling_tool) const;

  std::uint32_t stops() const { return zupt_periods_; }
  // Why the last stop gave no azimuth update; empty when it did.
  const std::string& field_warning() const { return last_field_warning_; }

 private:
  void still_updates(FilterState& filter, bool period_end, double dt_nominal, bool use_mag,
                     const FieldReference& field, Counters& counters);
  // How far a stop's dip may be from the reference's before its field is called disturbed (rad).
  double dip_tolerance(double g) const;
  void magnetic_update(FilterState& filter, const FieldReference& field, Counters& counters);
  void tally_update(FilterState& filter, Counters& counters);
  void late_stop_end(FilterState& filter, double depth_tolerance_m) const;
  // What the gyros' unestimated g-sensitivity adds to their bias at a stop after a turn by angle.
  void gyro_g_bias_after_turn(FilterState& filter, double angle) const;
  void turned_since_last_stop(FilterState& filter) const;
  // A depth row came within the age of a held report: the feed measures the tool as it goes.
  bool depth_reporting(double t) const;
  void depth_update(FilterState& filter, double t, double dt_nominal, double depth_sd, bool still, Counters& counters);
  void lateral_velocity_update(FilterState& filter, Counters& counters);
  void axial_acceleration_update(FilterState& filter, const FilterState::Prediction& prediction, double t,
                                 Counters& counters);

  NavigatorConfig config_;
  StillStats zaru_stats_, mag_stats_;
  bool mag_done_this_period_ = false;
  std::uint32_t zupt_periods_ = 0;
  double depth0_ = 0;
  bool have_depth0_ = false;
  bool aligned_ = false;  // reports before it feed the swell's models only
  double last_depth_update_t_ = -1e300;
  std::optional<double> latest_depth_;
  HeaveFilter heave_;
  bool heave_said_ = false;
  std::optional<double> heave_found_since_;
  static constexpr double kHeaveSettledS = 120;
  std::vector<std::string> notices_;
  std::optional<Eigen::Quaterniond> last_stop_attitude_;  // at the end of the last stop
  double latest_depth_t_ = 0;    // when the latest depth report came (its value first seen)
  double last_depth_row_t_ = 0;  // the last row that carried a depth
  // Pipe tally (tally_update): the stops counted as connections and the tally's distance at the last.
  std::size_t tally_stops_ = 0;
  double tally_distance_ = 0;
  double stop_started_t_ = 0;
  double stop_lag_s_ = 0;
  bool stop_settled_ = false;  // the still period in progress has outlasted stop_settle_s
  // Mean square of the lateral-velocity innovations beyond what the filter's covariance explains
  // (m^2/s^2, x and y): the tool's real lateral velocity (vibration, whirl, what the lever arm's
  // model leaves), used where it is larger than nhc_sd^2.
  Eigen::Vector2d lateral_excess_ = Eigen::Vector2d::Zero();
  // The velocity the last epoch's updates left (the next epoch's mechanization starts from it).
  Eigen::Vector3d velocity_after_updates_ = Eigen::Vector3d::Zero();
  std::string last_field_warning_;
};

}  // namespace plumb::strapdown
