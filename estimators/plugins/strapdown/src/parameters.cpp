#include "plumb/strapdown/parameters.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "plumb/core/imu_grade.hpp"
#include "plumb/estimator/parameter_reader.hpp"

namespace plumb::strapdown {

using estimator::ParameterError;

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kDegPerHour = kDegToRad / 3600.0;       // deg/h -> rad/s
constexpr double kPerRootHour = 1.0 / 60.0;              // x/sqrt(h) -> x/sqrt(s)
constexpr double kMilliG = 9.80665e-3;                   // mg -> m/s^2

std::optional<double> optional_number(const estimator::ParameterReader& reader, const estimator::Parameters& given,
                                      const std::string& name, double min, double max) {
  const auto it = given.find(name);
  if (it == given.end() || it->second.empty()) return std::nullopt;
  return reader.number(name, min, max);
}

// pipe_joint_m (one length for every stop) or pipe_tally_m (a list), not both.
void parse_tally(const estimator::ParameterReader& r, const estimator::Parameters& given, NavigatorConfig& c) {
  const std::optional<double> joint = optional_number(r, given, "pipe_joint_m", 0.01, 100);
  const auto list = given.find("pipe_tally_m");
  const bool has_list = list != given.end() && !list->second.empty();
  if (joint && has_list) throw ParameterError("parameters 'pipe_joint_m' and 'pipe_tally_m' exclude each other: give one");
  c.pipe_tally_sd = r.number("pipe_tally_sd_m", 0, 10);
  c.pipe_connection_s = r.number("pipe_connection_s", 0, 1e5);
  if (joint) {
    c.pipe_tally_m = {*joint};
    c.pipe_tally_repeats = true;
    return;
  }
  if (!has_list) return;
  std::string text = list->second;
  for (char& ch : text) {
    if (ch == ',' || ch == ';') ch = ' ';
  }
  std::istringstream in(text);
  std::string item;
  while (in >> item) {
    std::size_t used = 0;
    double v = std::numeric_limits<double>::quiet_NaN();
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !(v >= 0 && v <= 100)) {
      throw ParameterError("parameter 'pipe_tally_m': '" + item + "' is not a joint length in [0, 100] m");
    }
    c.pipe_tally_m.push_back(v);
  }
}

}  // namespace

std::vector<estimator::ParameterSpec> parameter_specs() {
  return {
      {"latitude_deg", "45", "latitude of the collar (deg): the earth rate's split into north and down"},
      {"gravity", "", "local gravity (m/s^2); empty: learnt from the first still period"},
      {"gravity_sd", "0.002", "how well a given gravity is known, 1 sigma (m/s^2): a formula's value at the site is rarely better than 0.001"},
      {"field_uT", "", "reference total field (uT); empty: learnt from the first still period"},
      {"dip_deg", "", "reference dip (deg, positive down); empty: learnt from the first still period"},
      {"output_rate_hz", "1", "rows per second from the end of alignment on"},
      {"use_magnetometer", "1", "use magnetometers for stillness and azimuth (0: gyros and accelerometers only)"},
      {"initial_azimuth_deg", "", "tool azimuth at alignment (deg) when there is no trusted magnetometer; output azimuth is then 'relative'"},
      {"initial_azimuth_sd_deg", "0", "standard deviation of initial_azimuth_deg (deg)"},
      {"gyrocompass", "0", "azimuth from the earth rate at alignment (navigation-grade gyros only); azimuth is then 'true'"},
      {"declination_deg", "", "magnetic declination (deg, east positive); given: azimuths are true"},
      {"imu_grade", "tactical", "sensor noise preset: navigation, tactical or mems (the noise parameters below override it; noise not stated is also read off the data before alignment, and the larger is used)"},
      {"gyro_arw_deg_rt_h", "", "gyro angle random walk (deg/sqrt(h)); empty: from imu_grade"},
      {"accel_vrw_mps_rt_h", "", "accelerometer velocity random walk (m/s/sqrt(h)); empty: from imu_grade"},
      {"gyro_bias_dph", "", "gyro turn-on bias, 1 sigma per axis (deg/h); empty: from imu_grade"},
      {"accel_bias_mg", "", "accelerometer turn-on bias, 1 sigma per axis (mg); empty: from imu_grade"},
      {"gyro_scale_factor_ppm", "", "gyro scale-factor error, 1 sigma (ppm): rotary drilling turns the tool through 10^4 degrees or more between stops; empty: from imu_grade"},
      {"gyro_misalignment_mrad", "", "gyro axis misalignment, 1 sigma (mrad): the x and y gyros read this share of a rotary string's rate, which tilts the turning axis the navigator integrates; empty: from imu_grade"},
      {"accel_scale_factor_ppm", "", "accelerometer scale-factor error, 1 sigma per axis (ppm): with the misalignment below, a bias that depends on how gravity falls on the triad, so a tool that turned between two stops has a new one; empty: from imu_grade"},
      {"accel_misalignment_mrad", "", "accelerometer axis misalignment, 1 sigma (mrad); empty: from imu_grade"},
      {"gyro_g_sensitivity_dph_g", "", "gyro sensitivity to acceleration, 1 sigma per element (deg/h per g): a rotary string turns gravity through the sensor every revolution, and the part of it the turning does not average out drifts the tool's attitude; empty: from imu_grade"},
      {"gyro_bias_instability_dph", "0", "gyro bias wander reached over bias_time_s (deg/h, random walk)"},
      {"accel_bias_instability_mg", "0", "accelerometer bias wander reached over bias_time_s (mg, random walk)"},
      {"bias_time_s", "3600", "time over which the bias instabilities are reached (s)"},
      {"still_detector", "auto", "stillness detector: magnitude (|f|, |B|, gyro quiet), glrt (f and w only) or auto (glrt for a tool with neither a magnetometer nor a measured depth before alignment: a foot or a hand; magnitude for a drilling tool)"},
      {"still_window_s", "0.05", "detector window (s; at least 3 samples)"},
      {"min_still_s", "0.5", "shortest still period used (s); 0.05 for foot-mounted or hand-held tools"},
      {"still_hysteresis", "1.5", "a still period ends when a test fails by this factor times its threshold"},
      {"still_accel_tol", "0.05", "magnitude detector: | |f| - g | limit per sample (m/s^2; never below 4 sigma of the noise)"},
      {"still_field_tol_uT", "5", "magnitude detector: | |B| - B0 | limit per sample (uT)"},
      {"still_gyro_tol_dph", "5", "gyro quiet: mean rate beyond earth rate and bias allowed (deg/h, plus the noise allowance)"},
      {"still_accel_drift_tol", "0.002", "specific-force steadiness: window mean vs still-period mean beyond the noise allowance (m/s^2)"},
      {"glrt_threshold", "15", "GLRT detector threshold (the statistic is about 6 for a still tool)"},
      {"still_depth_tol_m", "0.01", "with depth: largest depth change over 1 s of a still tool (m; never below 8 sigma of the depth noise)"},
      {"align_s", "30", "longest stretch of the first still period used for alignment (s)"},
      {"field_tol_uT", "0.5", "a stop's |B| further than this from the reference skips its azimuth update (uT)"},
      {"dip_tol_deg", "0.3", "a stop's dip further than this from the reference skips its azimuth update (deg; widened by three times what the accelerometers' stated bias and triad errors lean the dip between two toolfaces)"},
      {"mag_heading_sd_deg", "0.05", "magnetic heading model error per stop (deg), beside the noise"},
      {"mag_axial_bias_uT", "0.3", "magnetization of the drill string along the tool axis, 1 sigma (uT): it turns the magnetic azimuth the same way at every stop; 0: not modelled"},
      {"mag_axial_bias_learnt", "0", "1: estimate the string's magnetization from the run; 0: keep it at its stated sigma (a consider state). Only axis directions far apart tell it from the azimuth: within one hole direction an estimate learnt the gyros' drift instead (an outside horizontal MEMS run: 1.35 deg off learnt, 1.18 kept)"},
      {"mag_update_s", "5", "field averaged this long per stop for the azimuth update (s)"},
      {"kf_rate_hz", "20", "filter epochs per second (covariance propagation, updates, smoother storage)"},
      {"zupt_sd_mps", "0.001", "velocity of a still tool, 1 sigma (m/s)"},
      {"zero_rate_interval_s", "1", "gyro data averaged per zero-rate update at stops (s)"},
      {"tilt_update", "0", "separate accelerometer tilt update at stops (1: counts the accelerometer noise twice with the zero-velocity updates)"},
      {"lateral_velocity_update", "1", "while moving, lateral velocity zero in the tool frame (a drilling tool; 0 for a foot, hand-carried or vehicle-mounted sensor)"},
      {"nhc_sd_mps", "0.01", "lateral velocity of a drilling tool, 1 sigma (m/s)"},
      {"stop_lag_s", "2", "a drilling tool's filter runs this far behind the stillness detector: a stop that ends takes back its last stop_lag_s of zero-velocity updates (a string that speeds up slowly is seen moving late), and one shorter than that is none; once aligned, every row comes this much later, also in a live stream (s; 0: no lag; a foot or a hand, without lateral_velocity_update or with the GLRT detector, has none, nor a run whose readings carry depth before alignment: the depth test sees a slow start itself)"},
      {"stop_settle_s", "2", "without depth, a drilling string that slows over seconds looks still before it is: for this long after a stop is confirmed its velocity is zero only within rop_sd_mps, and a stop that ends sooner was none (s; 0: every stop at once)"},
      {"rop_sd_mps", "0.02", "rate of penetration, 1 sigma (m/s): a still period's end is seen late when the string speeds up slowly, and the tool may already move at this speed"},
      {"axial_accel_sd_mps2", "0.02", "without depth, how fast the rate of penetration changes: the string's acceleration along the tool axis over a second, 1 sigma (m/s^2); while the tool moves the navigator holds its own along-axis acceleration to it, which keeps its speed and the tilt from drifting together (0: not)"},
      {"max_rop_m_per_h", "180", "without depth or a pipe tally, the fastest the string is drilled (m/h): a slide that starts smoothly and runs straight looks still, so through every stop the position's sigma grows at this speed and the attitude's allows for the speed-up it may hide (0: not allowed for)"},
      {"depth_sd_m", "", "measured depth noise, 1 sigma (m); empty: 0.01 or what the depth reports show before alignment, whichever is larger"},
      {"depth_interval_s", "1", "seconds between measured-depth updates"},
      {"pipe_joint_m", "", "no depth sensor: every stop after the alignment is a connection that ran in one joint of this length (m)"},
      {"pipe_tally_m", "", "no depth sensor: the joints run in after each stop, stop by stop, comma-separated (m; the alignment's stop is the first; 0 for a stop without a connection)"},
      {"pipe_tally_sd_m", "0.02", "how well each joint of the tally is measured, 1 sigma (m)"},
      {"pipe_connection_s", "20", "with a tally: a still period this long is a connection (a pause while drilling is shorter) (s)"},
      {"lever_arm_sd_m", "0.01", "how far the accelerometers may sit off the tool axis, 1 sigma (m): turning, they feel its centripetal acceleration; 0: not modelled"},
      {"imu_samples", "instant", "what a reading is: instant (the value at its time stamp) or mean (the mean over its interval, stamped at the middle, as integrating sensors and decimating converters report)"},
      {"time_tag_sd_s", "0.0005", "how well a reading's time stamp gives the instant it stands for, 1 sigma (s): the toolface of a turning tool is uncertain by its rate times this"},
      {"toolface_switch_deg", "5", "below this inclination the rows name the toolface from north as the one to steer by, with its sigma: the magnetic toolface (magnetic_toolface_deg, from the navigator's attitude and the reference field) or, without a magnetometer, the gyro toolface; the gravity toolface and the azimuth are weakly defined there (deg; 0: never)"},
      {"smooth", "0", "offline backward (RTS) smoother: push() emits nothing, flush() emits every row smoothed"},
      {"max_gap_s", "1", "a time step longer than this is a gap: reported, bridged by prediction only (s)"},
      {"accel_range_g", "", "accelerometer range, +- on each axis (g, datasheet); a reading at or beyond it is clipped: the row says so and the step's sigma allows for what the clipped part could hide; empty: the grade's (navigation 25, tactical 40, mems 16)"},
      {"gyro_range_dps", "", "gyro range, +- on each axis (deg/s, datasheet); a reading at or beyond it is clipped, as for the accelerometers; empty: the grade's (navigation 500, tactical 1000, mems 2000)"},
      {"accel_shock_max_g", "0", "the largest acceleration the tool meets (g, its shock rating or the string's shock log): a clipped accelerometer reading may hide up to this less the range, added to the velocity's process noise; 0: not added (clipped readings are still counted, noticed and said on the rows: on the simulator's rebounding 30 g shocks the added noise made the attitude's sigma worse, docs/navigator.md)"},
      {"gyro_rate_max_dps", "3000", "the fastest the tool turns (deg/s; stick-slip's slip phase reaches 2-3 times the string's mean speed): a clipped gyro reading may hide up to this less the range"},
      {"gyro_bias_temp_dph_per_c", "0", "gyro bias temperature coefficient (deg/h per degC, datasheet; the same on every axis): readings that carry the tool's temperature are corrected by it times the change since the first reading, and what it is not known to (bias_temp_sd) widens the bias's sigma as the temperature changes; 0: not known, the readings stay as they are and the grade's typical coefficient (navigation 0.002, tactical 0.05, mems 0.2) widens the sigma instead, said in a notice"},
      {"accel_bias_temp_mg_per_c", "0", "accelerometer bias temperature coefficient (mg per degC, datasheet), as for the gyros; 0: not known (the grade's typical navigation 0.002, tactical 0.01, mems 0.05 widens the sigma)"},
      {"bias_temp_sd", "0.3", "how well the stated temperature coefficients are known, 1 sigma as a fraction of them (a datasheet's typical value: parts spread about it by some 20-30 %)"},
      {"use_temperature", "1", "use the tool's temperature on the readings that carry it (the correction and the bias's widening above; 0: ignore it)"},
      {"gyro_time_offset_s", "0", "gyro readings were measured this long after their time stamp (s)"},
      {"notice_after_s", "60", "data without alignment this long: the log says once which stillness test fails and what to change (s)"},
      {"no_stop_notice_s", "3600", "aligned, but no still period this long: the log says so once (s)"},
  };
}

NavigatorConfig parse_parameters(const estimator::Parameters& given) {
  static const std::vector<estimator::ParameterSpec> specs = parameter_specs();
  const estimator::ParameterReader r(given, specs);
  NavigatorConfig c;
  c.latitude = r.number("latitude_deg", -90, 90) * kDegToRad;
  c.gravity = optional_number(r, given, "gravity", 0.1, 100);
  c.gravity_sd = r.number("gravity_sd", 0, 1);
  c.field_uT = optional_number(r, given, "field_uT", 0.01, 1000);
  if (auto dip = optional_number(r, given, "dip_deg", -90, 90)) c.dip = *dip * kDegToRad;
  c.output_rate_hz = r.number("output_rate_hz", 1e-4, 1e4);
  if (c.output_rate_hz <= 0) throw ParameterError("parameter 'output_rate_hz' must be > 0");
  c.use_magnetometer = r.boolean("use_magnetometer");
  if (auto a = optional_number(r, given, "initial_azimuth_deg", -360, 360)) c.initial_azimuth = *a * kDegToRad;
  c.initial_azimuth_sd = r.number("initial_azimuth_sd_deg", 0, 180) * kDegToRad;
  c.gyrocompass = r.boolean("gyrocompass");
  if (auto d = optional_number(r, given, "declination_deg", -180, 180)) c.declination = *d * kDegToRad;
  if (c.gyrocompass && c.initial_azimuth) {
    throw ParameterError("parameters 'gyrocompass' and 'initial_azimuth_deg' exclude each other: give one azimuth source");
  }

  const auto grade_it = given.find("imu_grade");
  const std::string grade_name = grade_it == given.end() ? "tactical" : grade_it->second;
  // The presets: the table the survey's model of a navigator's stations reads too.
  const ImuGradeFigures* grade = find_imu_grade(grade_name);
  if (grade == nullptr) {
    throw ParameterError("parameter 'imu_grade': '" + grade_name + "' is not one of navigation, tactical, mems");
  }
  const std::optional<double> arw = optional_number(r, given, "gyro_arw_deg_rt_h", 0, 100);
  const std::optional<double> vrw = optional_number(r, given, "accel_vrw_mps_rt_h", 0, 100);
  c.gyro_arw = arw.value_or(grade->gyro_arw_deg_rt_h) * kDegToRad * kPerRootHour;
  c.accel_vrw = vrw.value_or(grade->accel_vrw_mps_rt_h) * kPerRootHour;
  c.gyro_noise_stated = arw.has_value();
  c.accel_noise_stated = vrw.has_value();
  c.gyro_bias_sd = optional_number(r, given, "gyro_bias_dph", 0, 1e5).value_or(grade->gyro_bias_dph) * kDegPerHour;
  c.accel_bias_sd = optional_number(r, given, "accel_bias_mg", 0, 1e4).value_or(grade->accel_bias_mg) * kMilliG;
  c.gyro_scale_sd = optional_number(r, given, "gyro_scale_factor_ppm", 0, 1e5).value_or(grade->gyro_scale_ppm) * 1e-6;
  c.gyro_misalignment_sd =
      optional_number(r, given, "gyro_misalignment_mrad", 0, 1e3).value_or(grade->gyro_misalignment_mrad) * 1e-3;
  c.accel_scale_sd =
      optional_number(r, given, "accel_scale_factor_ppm", 0, 1e5).value_or(grade->accel_scale_ppm) * 1e-6;
  c.accel_misalignment_sd =
      optional_number(r, given, "accel_misalignment_mrad", 0, 1e3).value_or(grade->accel_misalignment_mrad) * 1e-3;
  c.gyro_g_sensitivity_sd = optional_number(r, given, "gyro_g_sensitivity_dph_g", 0, 1e6).value_or(grade->gyro_g_dph_g) *
                            kDegPerHour / 9.80665;
  c.gyro_bias_instability = r.number("gyro_bias_instability_dph", 0, 1e5) * kDegPerHour;
  c.accel_bias_instability = r.number("accel_bias_instability_mg", 0, 1e4) * kMilliG;
  c.bias_time_s = r.number("bias_time_s", 1, 1e7);
  c.accel_range = optional_number(r, given, "accel_range_g", 0.1, 1e5).value_or(grade->accel_range_g) * kMilliG * 1000.0;
  c.gyro_range = optional_number(r, given, "gyro_range_dps", 1, 1e6).value_or(grade->gyro_range_dps) * kDegToRad;
  c.accel_shock_max = r.number("accel_shock_max_g", 0, 1e5) * kMilliG * 1000.0;
  c.gyro_rate_max = r.number("gyro_rate_max_dps", 0, 1e6) * kDegToRad;

  const auto det = given.find("still_detector");
  const std::string detector = det == given.end() ? "auto" : det->second;
  if (detector == "auto") {
    c.detector = DetectorChoice::Auto;
  } else if (detector == "magnitude") {
    c.detector = DetectorChoice::Magnitude;
  } else if (detector == "glrt") {
    c.detector = DetectorChoice::Glrt;
  } else {
    throw ParameterError("parameter 'still_detector': '" + detector + "' is not one of auto, magnitude, glrt");
  }
  c.still_window_s = r.number("still_window_s", 0, 60);
  c.min_still_s = r.number("min_still_s", 0, 3600);
  c.still_hysteresis = r.number("still_hysteresis", 1, 100);
  c.still_accel_tol = r.number("still_accel_tol", 1e-6, 100);
  c.still_field_tol_uT = r.number("still_field_tol_uT", 1e-6, 1000);
  c.still_gyro_tol = r.number("still_gyro_tol_dph", 0, 1e6) * kDegPerHour;
  c.glrt_threshold = r.number("glrt_threshold", 1e-3, 1e9);
  c.still_accel_drift_tol = r.number("still_accel_drift_tol", 0, 100);
  c.still_depth_tol_m = r.number("still_depth_tol_m", 1e-6, 100);
  c.align_s = r.number("align_s", 0, 3600);
  c.field_tol_uT = r.number("field_tol_uT", 0, 1000);
  c.dip_tol = r.number("dip_tol_deg", 0, 90) * kDegToRad;
  c.mag_heading_sd = r.number("mag_heading_sd_deg", 0, 90) * kDegToRad;
  c.mag_axial_bias_sd = r.number("mag_axial_bias_uT", 0, 100);
  c.mag_axial_bias_learnt = r.boolean("mag_axial_bias_learnt");
  c.mag_update_s = r.number("mag_update_s", 0, 3600);
  c.kf_rate_hz = r.number("kf_rate_hz", 0.01, 1e4);
  c.zupt_sd = r.number("zupt_sd_mps", 1e-9, 10);
  c.zaru_interval_s = r.number("zero_rate_interval_s", 0, 3600);
  c.tilt_update = r.boolean("tilt_update");
  c.lateral_velocity_update = r.boolean("lateral_velocity_update");
  c.nhc_sd = r.number("nhc_sd_mps", 1e-9, 10);
  c.stop_lag_s = r.number("stop_lag_s", 0, 60);
  c.stop_settle_s = r.number("stop_settle_s", 0, 600);
  c.rop_sd = r.number("rop_sd_mps", 0, 10);
  c.axial_accel_sd = r.number("axial_accel_sd_mps2", 0, 100);
  c.max_rop = r.number("max_rop_m_per_h", 0, 3600) / 3600.0;
  const std::optional<double> depth_sd = optional_number(r, given, "depth_sd_m", 1e-9, 100);
  c.depth_sd = depth_sd.value_or(0.01);
  c.depth_noise_stated = depth_sd.has_value();
  c.depth_interval_s = r.number("depth_interval_s", 0, 3600);
  c.lever_arm_sd = r.number("lever_arm_sd_m", 0, 1);
  parse_tally(r, given, c);
  const auto samples = given.find("imu_samples");
  const std::string sample_kind = samples == given.end() ? "instant" : samples->second;
  if (sample_kind != "instant" && sample_kind != "mean") {
    throw ParameterError("parameter 'imu_samples': '" + sample_kind + "' is not one of instant, mean");
  }
  c.samples_are_means = sample_kind == "mean";
  c.time_tag_sd = r.number("time_tag_sd_s", 0, 1);
  c.toolface_switch = r.number("toolface_switch_deg", 0, 90) * kDegToRad;
  c.smooth = r.boolean("smooth");
  c.max_gap_s = r.number("max_gap_s", 1e-6, 1e6);
  c.gyro_time_offset_s = r.number("gyro_time_offset_s", -1, 1);
  c.gyro_bias_temp = r.number("gyro_bias_temp_dph_per_c", -1e3, 1e3) * kDegPerHour;
  c.accel_bias_temp = r.number("accel_bias_temp_mg_per_c", -1e3, 1e3) * kMilliG;
  c.bias_temp_sd = r.number("bias_temp_sd", 0, 10);
  c.default_gyro_bias_temp = grade->gyro_temp_dph_c * kDegPerHour;
  c.default_accel_bias_temp = grade->accel_temp_mg_c * kMilliG;
  c.use_temperature = r.boolean("use_temperature");
  c.notice_after_s = r.number("notice_after_s", 0, 1e7);
  c.no_stop_notice_s = r.number("no_stop_notice_s", 0, 1e7);
  return c;
}

}  // namespace plumb::strapdown
