// The strapdown navigator: input checks, alignment, mechanization, stillness, the error-state
// filter and its measurements, output rows and the optional backward smoother. Plain C++ (no
// plugin API): the plugin (strapdown_estimator.cpp) and the tests drive it through push/flush.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "plumb/core/estimate.hpp"
#include "plumb/core/sample.hpp"
#include "plumb/strapdown/alignment.hpp"
#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/mechanization.hpp"
#include "plumb/strapdown/noise_floor.hpp"
#include "plumb/strapdown/smoother.hpp"
#include "plumb/strapdown/stillness.hpp"

namespace plumb::strapdown {

enum class DetectorChoice { Auto, Magnitude, Glrt };

// Every setting in SI units (radians, seconds, m/s^2, rad/s); parameters.hpp maps the plugin's
// named parameters onto it.
struct NavigatorConfig {
  double latitude = 45.0 * 3.14159265358979323846 / 180.0;
  std::optional<double> gravity;       // m/s^2; learnt from the first still period when absent
  double gravity_sd = 0.002;           // m/s^2: how well a given gravity is known (the filter's dg state)
  std::optional<double> field_uT;      // reference |B|
  std::optional<double> dip;           // reference dip
  double output_rate_hz = 1;
  bool use_magnetometer = true;
  std::optional<double> initial_azimuth;     // tool azimuth at alignment (no magnetometer)
  double initial_azimuth_sd = 0;
  bool gyrocompass = false;
  std::optional<double> declination;         // true = magnetic + declination
  // Stillness.
  DetectorChoice detector = DetectorChoice::Auto;
  double still_window_s = 0.05;
  double min_still_s = 0.5;
  double still_hysteresis = 1.5;
  double still_accel_tol = 0.05;       // m/s^2
  double still_field_tol_uT = 5;
  double still_gyro_tol = 5.0 * 3.14159265358979323846 / 180.0 / 3600.0;  // rad/s
  double glrt_threshold = 15;
  double still_accel_drift_tol = 0.002;  // m/s^2
  double still_depth_tol_m = 0.01;
  double align_s = 30;                 // longest stretch of the first still period used to align
  // Azimuth gating: a stop whose field disagrees with the reference gives no azimuth update.
  double field_tol_uT = 0.5;
  double dip_tol = 0.3 * 3.14159265358979323846 / 180.0;
  double mag_heading_sd = 0.05 * 3.14159265358979323846 / 180.0;  // model error per still period
  double mag_update_s = 5;             // field averaged this long (or the whole period) per update
  double mag_axial_bias_sd = 0.3;      // drill-string magnetization along the tool axis, 1 sigma (uT)
  // Sensor model (per axis).
  double gyro_arw = 0.05 * 3.14159265358979323846 / 180.0 / 60.0;   // rad/sqrt(s)
  double accel_vrw = 0.03 / 60.0;                                   // m/s/sqrt(s)
  double gyro_bias_sd = 1.0 * 3.14159265358979323846 / 180.0 / 3600.0;  // rad/s, turn-on
  double accel_bias_sd = 0.3e-3 * 9.80665;                          // m/s^2
  double gyro_scale_sd = 100e-6;        // scale-factor error about the tool axis, 1 sigma (fraction)
  double gyro_misalignment_sd = 0.1e-3; // x and y gyros' share of a rate about the tool axis, 1 sigma (rad)
  double gyro_g_sensitivity_sd = 1.0 * 3.14159265358979323846 / 180.0 / 3600.0 / 9.80665;  // per element, 1 sigma (rad/s per m/s^2)
  double gyro_bias_instability = 0.0;  // rad/s reached over bias_time_s (random walk)
  double accel_bias_instability = 0.0;
  double bias_time_s = 3600;
  // Measurements.
  double kf_rate_hz = 20;
  double zupt_sd = 1e-3;               // m/s
  double zaru_interval_s = 1;          // gyro means per zero-rate update
  bool tilt_update = false;            // separate accelerometer tilt update at stops
  // While moving, lateral velocity zero in the tool frame: a drilling tool moves along its axis;
  // a foot, a hand-carried or a vehicle-mounted sensor does not.
  bool lateral_velocity_update = true;
  double nhc_sd = 0.01;                // m/s
  double rop_sd = 0.02;                // rate of penetration, 1 sigma (m/s): the speed a stop's end may be seen late at
  double depth_sd = 0.01;              // m
  double depth_interval_s = 1;
  // No depth sensor: a pipe tally. Joint i is run in after stop i (the alignment's stop is stop 0),
  // so stop k stands at the sum of the first k joints from the alignment. A still period counts as
  // a connection once it has lasted pipe_connection_s (a pause while drilling is shorter), and
  // gives its update then. One length repeats for every stop; the sigma is per joint and adds up.
  std::vector<double> pipe_tally_m;
  bool pipe_tally_repeats = false;
  double pipe_tally_sd = 0.02;         // m per joint
  double pipe_connection_s = 20;
  // How far the accelerometers may sit off the tool axis (1 sigma, m; the filter's lever-arm
  // states). 0: not modelled (nor without lateral_velocity_update or with the GLRT detector: a foot
  // or a hand has no tool axis).
  double lever_arm_sd = 0.01;
  // Whether the user stated the noise (parameters.cpp: the figures given, not a preset). What was
  // not stated is read off the data before alignment (noise_floor.hpp) for the magnitude detector
  // and, where it is larger than the preset, for the filter too.
  bool gyro_noise_stated = true;
  bool accel_noise_stated = true;
  bool depth_noise_stated = true;
  // Never silent: data this long without alignment, or this long aligned without a stop, is said
  // once (take_notices), with the detector's test that fails and the parameter to change.
  double notice_after_s = 60;
  double no_stop_notice_s = 3600;
  // Each reading is the mean over its interval (an integrating sensor, a decimating converter),
  // stamped at the interval's middle, instead of an instant's value.
  bool samples_are_means = false;
  // How well a reading's time stamp gives the instant it stands for (jitter, a converter's group
  // delay), 1 sigma (s): the toolface of a tool turning at w is uncertain by w times this.
  double time_tag_sd = 0.5e-3;
  // Output and offline.
  bool smooth = false;
  double max_gap_s = 1.0;
  double gyro_time_offset_s = 0;       // gyro stamps lag the true gyro time by this (s)
};

class Navigator {
 public:
  explicit Navigator(const NavigatorConfig& config = {});
  // Counter pointers point into counters_: a copy would bump the original's; a move keeps the nodes.
  Navigator(const Navigator&) = delete;
  Navigator& operator=(const Navigator&) = delete;
  Navigator(Navigator&&) = default;
  Navigator& operator=(Navigator&&) = default;
  void configure(const NavigatorConfig& config);
  // Samples oldest first; appends the rows they complete (none in smoothing mode).
  void push(const Sample& s, std::vector<Estimate>& out);
  // End of stream: the rows still pending (all of them, smoothed, in smoothing mode).
  void flush(std::vector<Estimate>& out);
  const std::map<std::string, std::uint64_t>& counters() const { return counters_; }
  // What the navigator has to say once (a run that cannot align and why, the noise it measured):
  // returns and forgets the messages since the last call.
  std::vector<std::string> take_notices() { return std::exchange(notices_, {}); }

  // Introspection for tests.
  bool aligned() const { return aligned_; }
  const NavState& state() const { return x_; }
  const Eigen::Vector3d& gyro_bias() const { return bg_; }
  const Eigen::Vector3d& accel_bias() const { return ba_; }
  double gyro_scale() const { return gyro_spin_.z(); }
  Eigen::Vector2d gyro_leak() const { return gyro_spin_.head<2>(); }
  Eigen::Vector2d gyro_g() const { return gyro_g_; }
  double mag_axial_bias() const { return mag_axial_; }
  const StateMatrix& covariance() const { return kf_.covariance(); }
  bool still() const { return detector_.still(); }
  double time() const { return last_t_.value_or(0.0); }
  std::size_t smoother_epochs() const { return smoother_.size(); }

 private:
  struct Input {
    double t = 0;
    Eigen::Vector3d f, w;
    std::optional<Eigen::Vector3d> b;
    std::optional<double> depth;
    bool gyro_bad = false;  // saturated: the rate is the last good one
    bool accel_bad = false;
  };
  void reset();
  void count(const char* name, std::uint64_t n = 1) { counters_[name] += n; }
  bool accept(const Sample& s, Input& in);
  void shift_gyro(Input in, std::vector<Estimate>& out);
  void process(const Input& in, std::vector<Estimate>& out);
  void before_alignment(const Input& in, std::vector<Estimate>& out);
  void align(const Input& in);
  Eigen::Matrix3d initial_attitude(const Eigen::Vector3d& f, const Eigen::Vector3d& w, const Eigen::Vector3d& b,
                                   bool mag, double& heading_sd);
  StateMatrix initial_covariance(const Eigen::Vector3d& f, double heading_sd, double sd_mean_f) const;
  void first_measurements(const StillStats& stats, double sd_mean_f, double dt);
  void epoch(const Input& in, std::vector<Estimate>& out);
  void still_updates(bool period_end);
  void magnetic_update();
  void emit(double t, std::vector<Estimate>& out);
  Estimate row(double t) const;
  void fill_attitude(Estimate& e, const NavState& x, const StateMatrix& p) const;
  void apply(const StateVector& dx);
  StillnessInput detector_input(const Input& in) const;
  ImuReading reading(const Input& in, const Input* earlier = nullptr) const;
  void refresh_noise(double dt);
  void refresh_detector_allowances();
  double field_azimuth() const;
  std::string reason() const;
  void watch_before_alignment(const Input& in);
  void adopt_noise_floor();
  bool noise_known() const;
  void adopt_measured_noise(double dt);
  void watch_for_stops(double t);
  std::string failing_test_text() const;
  void refresh_depth_tolerance();
  void tally_update();
  void late_stop_end();

  NavigatorConfig config_;
  std::map<std::string, std::uint64_t> counters_;
  std::uint64_t* samples_counter_ = nullptr;
  std::uint64_t* accepted_counter_ = nullptr;
  // Input.
  std::optional<double> last_t_;
  std::optional<Eigen::Vector3d> last_good_w_, last_good_f_;
  std::deque<Input> shift_queue_;
  std::deque<std::pair<double, Eigen::Vector3d>> gyro_history_;
  double dt_nominal_ = 0;
  bool saw_gyro_ = false, saw_no_gyro_ = false, saw_mag_ = false;
  // Environment (given or learnt).
  // Given, or |mean f| at alignment; corrected by the filter's gravity state from then on.
  double g_ = 9.80665;
  std::optional<double> b0_, dip0_;
  bool accel_in_g_ = false;
  double accel_in_g_level_ = 0;
  bool use_mag_ = false;  // magnetometer used for azimuth
  std::string azimuth_reference_ = "magnetic";
  // Filter.
  bool aligned_ = false;
  double aligned_at_ = 0;
  NavState x_;
  Eigen::Vector3d bg_ = Eigen::Vector3d::Zero(), ba_ = Eigen::Vector3d::Zero();
  Eigen::Vector2d lever_ = Eigen::Vector2d::Zero();  // accelerometers' offset from the tool axis (x, y), m
  // The gyros' response to a rate w about the tool axis beyond it: the x and y gyros read
  // gyro_spin_.x() w and gyro_spin_.y() w (misalignment), the z gyro (1 + gyro_spin_.z()) w.
  Eigen::Vector3d gyro_spin_ = Eigen::Vector3d::Zero();
  Eigen::Vector2d gyro_g_ = Eigen::Vector2d::Zero();  // (g_s, g_a): see index::kGyroG
  double mag_axial_ = 0;   // the magnetometers' bias along the tool axis, uT
  bool lever_model_ = false;
  bool drilling_tool_ = false;  // a tool axis to turn about and move along (align())
  ErrorStateFilter kf_;
  ProcessNoise noise_;
  Mechanization mech_{Eigen::Vector3d::Zero(), 9.80665};
  StepIntegrals integrals_;
  std::optional<Input> prev_, prev2_;
  double last_epoch_t_ = 0;
  StateVector correction_ = StateVector::Zero();
  StillnessDetector detector_;
  double aligned_gyro_tol_ = 0;  // the detector's extra gyro tolerance once aligned (refresh_detector_allowances)
  // The biases the detector takes out once aligned: the filter's, within 3 sigma of the figures.
  Eigen::Vector3d detector_ba_ = Eigen::Vector3d::Zero(), detector_bg_ = Eigen::Vector3d::Zero();
  StillnessState still_state_;
  StillStats align_stats_, zaru_stats_, mag_stats_;
  bool mag_done_this_period_ = false;
  double depth0_ = 0;
  bool have_depth0_ = false;
  double last_depth_update_t_ = -1e300;
  std::optional<double> latest_depth_;
  double latest_depth_t_ = 0;    // when the latest depth report came (its value first seen)
  double last_depth_row_t_ = 0;  // the last row that carried a depth
  std::uint32_t zupt_periods_ = 0;
  // Pipe tally (tally_update): the stops counted as connections and the tally's distance at the last.
  std::size_t tally_stops_ = 0;
  double tally_distance_ = 0;
  double stop_started_t_ = 0;
  // Mean square of the lateral-velocity innovations beyond what the filter's covariance explains
  // (m^2/s^2, x and y): the tool's real lateral velocity (vibration, whirl, what the lever arm's
  // model leaves), used where it is larger than nhc_sd^2.
  Eigen::Vector2d lateral_excess_ = Eigen::Vector2d::Zero();
  std::string last_field_warning_;
  // Never silent (watch_before_alignment, watch_for_stops).
  NoiseFloor noise_floor_;
  std::size_t floor_blocks_used_ = 0;
  // Per-sample noise read off the data, for what the user did not state (the magnitude detector).
  std::optional<double> measured_sigma_a_, measured_sigma_w_, measured_depth_sd_;
  double depth_sd_ = 0.01;  // the filter's depth noise: stated, or the larger of the default and the floor
  std::optional<double> first_t_;
  StillnessTally tally_;     // what kept the detector from a still period since alignment or the last stop
  bool align_notice_given_ = false, stop_notice_given_ = false;
  double last_still_t_ = 0;
  std::vector<std::string> notices_;
  double gap_warning_until_ = -1;
  // Output.
  double next_output_t_ = 0;
  bool output_started_ = false;
  double last_row_t_ = 0;
  StillStats row_stats_;  // readings since the last row (totals, dip, rpm)
  Eigen::Vector3d last_b_ = Eigen::Vector3d::Zero();
  bool last_b_valid_ = false;
  // Smoothing.
  RtsSmoother smoother_;
  StateMatrix last_phi_ = StateMatrix::Identity();
  double last_phi_dt_ = 0;
  struct PendingRow {
    Estimate row;
    std::optional<std::size_t> epoch;  // smoother epoch of the row (none before alignment)
  };
  std::vector<PendingRow> pending_;
};

}  // namespace plumb::strapdown
