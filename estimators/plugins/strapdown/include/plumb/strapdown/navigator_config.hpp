// The navigator's settings, in SI units, shared by the navigator and its parts.
#pragma once

#include <optional>
#include <vector>

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
  bool mag_axial_bias_learnt = false;  // estimated from the run; false: a consider state (its sigma kept)
  // Sensor model (per axis).
  double gyro_arw = 0.05 * 3.14159265358979323846 / 180.0 / 60.0;   // rad/sqrt(s)
  double accel_vrw = 0.03 / 60.0;                                   // m/s/sqrt(s)
  double gyro_bias_sd = 1.0 * 3.14159265358979323846 / 180.0 / 3600.0;  // rad/s, turn-on
  double accel_bias_sd = 0.3e-3 * 9.80665;                          // m/s^2
  double gyro_scale_sd = 100e-6;        // scale-factor error about the tool axis, 1 sigma (fraction)
  double gyro_misalignment_sd = 0.1e-3; // x and y gyros' share of a rate about the tool axis, 1 sigma (rad)
  // The accelerometer triad's scale factors and misalignments, 1 sigma (fraction, rad): a bias that
  // depends on the orientation, new after the tool turns.
  double accel_scale_sd = 100e-6, accel_misalignment_sd = 0.1e-3;
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
  // A drilling tool's filter runs this far behind the stillness detector, so that a stop that ends
  // gives back the last stop_lag_s of its zero-velocity updates (stillness_lag.hpp); rows come this
  // much later (s). A foot or a hand (no tool axis) has none: its stances last a fraction of a second.
  double stop_lag_s = 2;
  double stop_settle_s = 2;            // a drilling tool may creep this long into a confirmed stop (s)
  double rop_sd = 0.02;                // rate of penetration, 1 sigma (m/s): the speed a stop's end may be seen late at
  // How fast the rate of penetration changes: the string's acceleration along the tool axis over a
  // second, 1 sigma (m/s^2). Without depth the navigator holds its own along-axis acceleration to it
  // while the tool moves (0: not).
  double axial_accel_sd = 0.02;
  // The fastest the string is drilled (m/s): without depth or a tally, a stop may be a slide this
  // fast that the sensors cannot see (unseen_motion.hpp). 0: not allowed for.
  double max_rop = 0.05;
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
  // Below this inclination the rows name the toolface from north (magnetic, or gyro without a
  // magnetometer) as the one to steer by, with its sigma (rad; 0: never).
  double toolface_switch = 5.0 * 3.14159265358979323846 / 180.0;
  bool smooth = false;
  double max_gap_s = 1.0;
  // The sensors' ranges (datasheet): a reading at or beyond one on any axis is clipped; and how far
  // beyond it the truth can plausibly be (a drilling tool's shocks, stick-slip's slip phase).
  double accel_range = 16 * 9.80665;      // m/s^2
  double gyro_range = 2000 * 3.14159265358979323846 / 180.0;  // rad/s
  double accel_shock_max = 0;              // m/s^2; 0: a clipped accelerometer adds no process noise
  double gyro_rate_max = 3000 * 3.14159265358979323846 / 180.0;  // rad/s
  double gyro_time_offset_s = 0;       // gyro stamps lag the true gyro time by this (s)
  // The biases' temperature coefficients (datasheet; rad/s and m/s^2 per degC; 0: not known), how
  // well they are known (1 sigma, a fraction of them), the grade's typical ones (the uncertainty
  // when not known), and whether readings that carry a temperature are used for it
  // (temperature_drift.hpp).
  double gyro_bias_temp = 0, accel_bias_temp = 0;
  double bias_temp_sd = 0.3;
  double default_gyro_bias_temp = 0.05 * 3.14159265358979323846 / 180.0 / 3600.0;
  double default_accel_bias_temp = 0.01 * 9.80665e-3;
  bool use_temperature = true;
};

}  // namespace plumb::strapdown
