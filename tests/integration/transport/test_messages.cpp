#include "test_messages.hpp"

#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

namespace plumb::test {

namespace {

// Each call returns a value no other call returns: field k gets a value derived from k.
class Distinct {
 public:
  double real() {
    ++k_;
    const double sign = (k_ % 2 == 0) ? 1.0 : -1.0;
    return sign * (static_cast<double>(k_) * 1.0009765625 + 1.0 / static_cast<double>(k_ + 2));  // not a short decimal
  }
  std::int64_t i64() { return -(std::int64_t{1} << 62) - static_cast<std::int64_t>(++k_); }
  std::uint64_t u64() { return (std::uint64_t{1} << 63) + static_cast<std::uint64_t>(++k_); }
  std::uint32_t u32() { return 0x80000000u + static_cast<std::uint32_t>(++k_); }
  unsigned seed() { return static_cast<unsigned>(++k_); }

 private:
  long k_ = 0;
};

template <std::size_t N> std::array<double, N> reals(Distinct& d) {
  std::array<double, N> a{};
  for (auto& x : a) x = d.real();
  return a;
}

topics::TriadCalibration triad(Distinct& d) {
  topics::TriadCalibration t;
  t.bias = reals<3>(d);
  t.sensitivity = reals<9>(d);
  t.second_order = reals<3>(d);
  t.bias_temp = reals<3>(d);
  t.scale_temp = reals<3>(d);
  return t;
}

// Flattens a message into (path, exact text) pairs in IDL order.
class Flattener {
 public:
  std::vector<std::pair<std::string, std::string>> fields;

  template <class M> void message(const std::string& prefix, const M& m) {
    topics::visit_fields(m, [&](const char* name, const auto& value) { this->value(prefix + name, value); });
  }

 private:
  void value(const std::string& path, const std::string& v) { fields.emplace_back(path, '"' + v + '"'); }
  void value(const std::string& path, double v) { fields.emplace_back(path, format("%a", v)); }
  void value(const std::string& path, std::int64_t v) { fields.emplace_back(path, std::to_string(v)); }
  void value(const std::string& path, std::uint64_t v) { fields.emplace_back(path, std::to_string(v)); }
  void value(const std::string& path, std::uint32_t v) { fields.emplace_back(path, std::to_string(v)); }
  template <std::size_t N> void value(const std::string& path, const std::array<double, N>& a) {
    for (std::size_t i = 0; i < N; ++i) value(path + "[" + std::to_string(i) + "]", a[i]);
  }
  template <class E> void value(const std::string& path, const std::vector<E>& v) {
    fields.emplace_back(path + ".length", std::to_string(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) message(path + "[" + std::to_string(i) + "].", v[i]);
  }
  template <class M> void value(const std::string& path, const M& nested) { message(path + ".", nested); }

  static std::string format(const char* fmt, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, fmt, v);
    return buffer;
  }
};

template <class M> std::string difference(const M& expected, const M& got) {
  Flattener e, g;
  e.message("", expected);
  g.message("", got);
  for (std::size_t i = 0; i < e.fields.size() && i < g.fields.size(); ++i) {
    if (e.fields[i] != g.fields[i]) {
      return e.fields[i].first + ": expected " + e.fields[i].second + ", got " + g.fields[i].second;
    }
  }
  if (e.fields.size() != g.fields.size()) return "different number of fields";
  return expected == got ? "" : "operator== differs but no field does";
}

}  // namespace

std::string pattern_string(std::size_t length, unsigned seed) {
  // Printable ASCII without space and quote characters, so that it survives shell and CSV output.
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_+.:;()[]";
  constexpr std::size_t n = sizeof kAlphabet - 1;
  std::string s(length, ' ');
  for (std::size_t i = 0; i < length; ++i) s[i] = kAlphabet[(seed * 7 + i * 13 + i / n) % n];
  return s;
}

topics::SensorBatch full_sensor_batch() {
  Distinct d;
  topics::SensorBatch b;
  b.tool_id = pattern_string(topics::kToolIdMax, d.seed());
  b.calibration_id = pattern_string(topics::kIdMax, d.seed());
  for (std::uint32_t i = 0; i < topics::kMaxSamplesPerBatch; ++i) {
    topics::SensorSample s;
    s.seq = d.u64();
    s.stamp_ns = d.i64();
    s.fx = d.real(); s.fy = d.real(); s.fz = d.real();
    s.bx = d.real(); s.by = d.real(); s.bz = d.real();
    s.wx = d.real(); s.wy = d.real(); s.wz = d.real();
    s.temp_c = d.real();
    s.flags = d.u32();
    b.samples.push_back(s);
  }
  // Extremes of the double range must cross bit for bit as well.
  b.samples[0].fx = std::numeric_limits<double>::max();
  b.samples[0].fy = std::numeric_limits<double>::lowest();
  b.samples[0].fz = std::numeric_limits<double>::denorm_min();
  b.samples[0].bx = -0.0;
  return b;
}

topics::SensorBatch empty_sensor_batch() { return {}; }

topics::Attitude full_attitude() {
  Distinct d;
  topics::Attitude a;
  a.tool_id = pattern_string(topics::kToolIdMax, d.seed());
  a.estimator = pattern_string(topics::kNameMax, d.seed());
  a.window_start_ns = d.i64();
  a.window_end_ns = d.i64();
  a.inclination_deg = d.real();
  a.azimuth_deg = d.real();
  a.gravity_toolface_deg = d.real();
  a.magnetic_toolface_deg = d.real();
  a.rpm = d.real();
  a.inclination_sd_deg = d.real();
  a.azimuth_sd_deg = d.real();
  a.toolface_sd_deg = d.real();
  a.dip_deg = d.real();
  a.total_g = d.real();
  a.total_b = d.real();
  a.samples_used = d.u32();
  a.flags = d.u32();
  a.reason = pattern_string(topics::kReasonMax, d.seed());
  return a;
}

topics::CalibrationCoefficients full_calibration() {
  Distinct d;
  topics::CalibrationCoefficients c;
  c.tool_id = pattern_string(topics::kToolIdMax, d.seed());
  c.calibration_id = pattern_string(topics::kIdMax, d.seed());
  c.stamp_ns = d.i64();
  c.reference_temp_c = d.real();
  c.temp_min_c = d.real();
  c.temp_max_c = d.real();
  c.thermometer = reals<4>(d);
  c.accelerometer = triad(d);
  c.magnetometer = triad(d);
  return c;
}

topics::ComponentStatus full_status() {
  Distinct d;
  topics::ComponentStatus s;
  s.component = pattern_string(topics::kComponentMax, d.seed());
  s.host = pattern_string(topics::kHostMax, d.seed());
  s.state = pattern_string(topics::kStateMax, d.seed());
  s.stamp_ns = d.i64();
  for (std::uint32_t i = 0; i < topics::kMaxCountersPerStatus; ++i) {
    s.counters.push_back({pattern_string(topics::kNameMax, d.seed()), d.u64()});
  }
  s.last_error = pattern_string(topics::kErrorMax, d.seed());
  return s;
}

topics::Truth full_truth() {
  Distinct d;
  topics::Truth t;
  t.tool_id = pattern_string(topics::kToolIdMax, d.seed());
  t.stamp_ns = d.i64();
  t.inclination_deg = d.real();
  t.azimuth_deg = d.real();
  t.toolface_deg = d.real();
  t.rpm = d.real();
  return t;
}

std::string first_difference(const topics::SensorBatch& e, const topics::SensorBatch& g) { return difference(e, g); }
std::string first_difference(const topics::Attitude& e, const topics::Attitude& g) { return difference(e, g); }
std::string first_difference(const topics::CalibrationCoefficients& e, const topics::CalibrationCoefficients& g) {
  return difference(e, g);
}
std::string first_difference(const topics::ComponentStatus& e, const topics::ComponentStatus& g) {
  return difference(e, g);
}
std::string first_difference(const topics::Truth& e, const topics::Truth& g) { return difference(e, g); }

std::string attitude_line(const topics::Attitude& a) {
  // Same format string as examples/c_attitude_listener/attitude_listener.c.
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer,
                "tool=%s estimator=%s end_ns=%lld inclination=%.17g azimuth=%.17g toolface=%.17g "
                "rpm=%.17g flags=%u reason=%s",
                a.tool_id.c_str(), a.estimator.c_str(), static_cast<long long>(a.window_end_ns), a.inclination_deg,
                a.azimuth_deg, a.gravity_toolface_deg, a.rpm, a.flags, a.reason.c_str());
  return buffer;
}

}  // namespace plumb::test
