#include "plumb/components/convert.hpp"

#include <cmath>

namespace plumb::components {

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
  m.flags = s.flags;
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
  a.tool_id = bounded(tool_id, topics::kToolIdMax);
  a.estimator = bounded(e.estimator, topics::kNameMax);
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
  using namespace topics::attitude_flags;
  a.flags = (e.valid ? kValid : 0) | (e.azimuth_valid ? kAzimuthValid : 0) | (e.toolface_valid ? kToolfaceValid : 0) |
            (e.rotating ? kRotating : 0) | (e.partial_window ? kPartialWindow : 0);
  a.reason = bounded(e.reason, topics::kReasonMax);
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
  using namespace topics::attitude_flags;
  e.valid = a.flags & kValid;
  e.azimuth_valid = a.flags & kAzimuthValid;
  e.toolface_valid = a.flags & kToolfaceValid;
  e.rotating = a.flags & kRotating;
  e.partial_window = a.flags & kPartialWindow;
  e.reason = a.reason;
  return e;
}

topics::Truth to_topic(const TruthSample& t, const std::string& tool_id) {
  topics::Truth m;
  m.tool_id = bounded(tool_id, topics::kToolIdMax);
  m.stamp_ns = seconds_to_ns(t.t);
  m.inclination_deg = t.inclination_deg;
  m.azimuth_deg = t.azimuth_deg;
  m.toolface_deg = t.toolface_deg;
  m.rpm = t.rpm;
  return m;
}

}  // namespace plumb::components
