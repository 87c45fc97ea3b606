#include "plumb/components/convert.hpp"

#include <cmath>

namespace plumb::components {

// The math libraries keep their own copy of the sample flags (they include no topic header):
// the wire values are the IDL's, and these must agree.
static_assert(flags::kAccelSaturated == topics::SAMPLE_ACCEL_SATURATED && flags::kMagSaturated == topics::SAMPLE_MAG_SATURATED &&
              flags::kGyroSaturated == topics::SAMPLE_GYRO_SATURATED && flags::kOutOfRange == topics::SAMPLE_OUT_OF_RANGE &&
              flags::kNotFinite == topics::SAMPLE_NOT_FINITE && flags::kGapBefore == topics::SAMPLE_GAP_BEFORE &&
              flags::kTimeBackwards == topics::SAMPLE_TIME_BACKWARDS && flags::kHasGyro == topics::SAMPLE_HAS_GYRO &&
              flags::kHasTemperature == topics::SAMPLE_HAS_TEMPERATURE && flags::kCalibrated == topics::SAMPLE_CALIBRATED &&
              flags::kTemperatureOutOfRange == topics::SAMPLE_TEMPERATURE_OUT_OF_RANGE &&
              flags::kNoMagnetometer == topics::SAMPLE_NO_MAGNETOMETER);

std::int64_t seconds_to_ns(double t) { return static_cast<std::int64_t>(std::llround(t * 1e9)); }
double ns_to_seconds(std::int64_t ns) { return static_cast<double>(ns) * 1e-9; }

std::string bounded(const std::string& s, std::size_t max) { return s.size() <= max ? s : s.substr(0, max); }

topics::SensorSample to_topic(const Sample& s) {
  topics::SensorSample m;
  m.seq = s.seq;
  m.stamp_ns = seconds_to_ns(s.t);
  m.fx = s.f.x(); m.fy = s.f.y(); m.fz = s.f.z();
  m.bx = s.b.x(); m.by = s.b.y(); m.bz = s.b.z();
  m.wx = s.w.x(); m.wy = s.w.y(); m.wz = s.w.z();
  m.temp_c = s.temp_c;
  m.flags = s.flags & ~flags::kHasDepth;  // the depth itself is not in the sample on the wire
  return m;
}

Sample from_topic(const topics::SensorSample& m) {
  Sample s;
  s.seq = m.seq;
  s.t = ns_to_seconds(m.stamp_ns);
  s.f = {m.fx, m.fy, m.fz};
  s.b = {m.bx, m.by, m.bz};
  s.w = {m.wx, m.wy, m.wz};
  s.temp_c = m.temp_c;
  s.flags = m.flags;
  return s;
}

topics::Attitude to_topic(const Estimate& e, const std::string& tool_id) {
  topics::Attitude a;
  a.tool_id = bounded(tool_id, topics::Attitude::kToolIdMax);
  a.estimator = bounded(e.estimator, topics::Counter::kNameMax);
  a.window_start_ns = seconds_to_ns(e.t_start);
  a.window_end_ns = seconds_to_ns(e.t_end);
  a.inclination_deg = e.inclination_deg;
  a.azimuth_deg = e.azimuth_deg;
  a.gravity_toolface_deg = e.gravity_toolface_deg;
  a.magnetic_toolface_deg = e.magnetic_toolface_deg;
  a.rpm = e.rpm;
  a.inclination_sd_deg = e.inclination_sd_deg;
  a.azimuth_sd_deg = e.azimuth_sd_deg;
  a.toolface_sd_deg = e.toolface_sd_deg;
  a.dip_deg = e.dip_deg;
  a.total_g = e.total_g;
  a.total_b = e.total_b;
  a.samples_used = e.samples_used;
  a.flags = (e.valid ? topics::ATTITUDE_VALID : 0) | (e.azimuth_valid ? topics::ATTITUDE_AZIMUTH_VALID : 0) |
            (e.toolface_valid ? topics::ATTITUDE_TOOLFACE_VALID : 0) | (e.rotating ? topics::ATTITUDE_ROTATING : 0) |
            (e.partial_window ? topics::ATTITUDE_PARTIAL_WINDOW : 0);
  a.reason = bounded(e.reason, topics::Attitude::kReasonMax);
  return a;
}

Estimate from_topic(const topics::Attitude& a) {
  Estimate e;
  e.estimator = a.estimator;
  e.t_start = ns_to_seconds(a.window_start_ns);
  e.t_end = ns_to_seconds(a.window_end_ns);
  e.inclination_deg = a.inclination_deg;
  e.azimuth_deg = a.azimuth_deg;
  e.gravity_toolface_deg = a.gravity_toolface_deg;
  e.magnetic_toolface_deg = a.magnetic_toolface_deg;
  e.rpm = a.rpm;
  e.inclination_sd_deg = a.inclination_sd_deg;
  e.azimuth_sd_deg = a.azimuth_sd_deg;
  e.toolface_sd_deg = a.toolface_sd_deg;
  e.dip_deg = a.dip_deg;
  e.total_g = a.total_g;
  e.total_b = a.total_b;
  e.samples_used = a.samples_used;
  e.valid = (a.flags & topics::ATTITUDE_VALID) != 0;
  e.azimuth_valid = (a.flags & topics::ATTITUDE_AZIMUTH_VALID) != 0;
  e.toolface_valid = (a.flags & topics::ATTITUDE_TOOLFACE_VALID) != 0;
  e.rotating = (a.flags & topics::ATTITUDE_ROTATING) != 0;
  e.partial_window = (a.flags & topics::ATTITUDE_PARTIAL_WINDOW) != 0;
  e.reason = a.reason;
  return e;
}

topics::Truth to_topic(const TruthSample& t, const std::string& tool_id) {
  topics::Truth m;
  m.tool_id = bounded(tool_id, topics::Attitude::kToolIdMax);
  m.stamp_ns = seconds_to_ns(t.t);
  m.inclination_deg = t.inclination_deg;
  m.azimuth_deg = t.azimuth_deg;
  m.toolface_deg = t.toolface_deg;
  m.rpm = t.rpm;
  return m;
}

}  // namespace plumb::components

namespace plumb::components {

topics::Navigation to_navigation(const Estimate& e, const std::string& tool_id) {
  topics::Navigation n;
  n.tool_id = bounded(tool_id, topics::Navigation::kToolIdMax);
  n.estimator = bounded(e.estimator, topics::Navigation::kEstimatorMax);
  n.stamp_ns = seconds_to_ns(e.t_end);
  const NavigationState nav = e.navigation.value_or(NavigationState{});
  n.north_m = nav.position_m[0], n.east_m = nav.position_m[1], n.down_m = nav.position_m[2];
  n.vn_mps = nav.velocity_mps[0], n.ve_mps = nav.velocity_mps[1], n.vd_mps = nav.velocity_mps[2];
  n.north_sd_m = nav.position_sd_m[0], n.east_sd_m = nav.position_sd_m[1], n.down_sd_m = nav.position_sd_m[2];
  n.vn_sd_mps = nav.velocity_sd_mps[0], n.ve_sd_mps = nav.velocity_sd_mps[1], n.vd_sd_mps = nav.velocity_sd_mps[2];
  n.inclination_deg = e.inclination_deg;
  n.azimuth_deg = e.azimuth_deg;
  n.toolface_deg = e.gravity_toolface_deg;
  n.inclination_sd_deg = e.inclination_sd_deg;
  n.azimuth_sd_deg = e.azimuth_sd_deg;
  n.toolface_sd_deg = e.toolface_sd_deg;
  n.flags = (e.valid && e.navigation ? topics::NAVIGATION_VALID : 0) | (nav.still ? topics::NAVIGATION_STILL : 0) |
            (e.navigation && !e.reason.starts_with("aligning") ? topics::NAVIGATION_ALIGNED : 0) | (e.azimuth_valid ? topics::NAVIGATION_AZIMUTH_VALID : 0);
  n.zero_velocity_updates = nav.zero_velocity_updates;
  n.azimuth_reference = bounded(nav.azimuth_reference, topics::Navigation::kAzimuthReferenceMax);
  n.reason = bounded(e.reason, topics::Navigation::kReasonMax);
  return n;
}

topics::MeasuredDepth to_depth(const Sample& s, const std::string& tool_id) {
  topics::MeasuredDepth d;
  d.tool_id = bounded(tool_id, topics::MeasuredDepth::kToolIdMax);
  d.stamp_ns = seconds_to_ns(s.t);
  d.depth_m = s.depth_m;
  d.flags = (s.flags & flags::kHasDepth) ? topics::DEPTH_VALID : 0;
  return d;
}

}  // namespace plumb::components
