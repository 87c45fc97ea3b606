#include "plumb/csv/coefficients_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "plumb/core/number.hpp"
#include "plumb/core/trim.hpp"

namespace plumb::csv {

namespace {

constexpr std::string_view kFormatName = "plumb-calibration";
constexpr int kNewestVersion = 2;

void write_exact(std::ostream& out, double x) {
  // Shortest representation that reads back to the same double: exact round trip.
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.write(buf, r.ptr - buf);
}

template <typename Vec>
void write_values(std::ostream& out, std::string_view key, const Vec& values) {
  out << key;
  for (double x : values) out << ' ', write_exact(out, x);
  out << '\n';
}

std::vector<double> as_vector(const Eigen::Vector3d& v) { return {v[0], v[1], v[2]}; }

std::vector<double> row_major(const Eigen::Matrix3d& m) {
  std::vector<double> out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.push_back(m(r, c));
  return out;
}

// Version-1 files stay byte-for-byte what they were: the version-2 keys are written only when the
// model has version-2 terms.
void write_triad(std::ostream& out, std::string_view prefix, const TriadModel& t, bool version2) {
  const std::string p(prefix);
  write_values(out, p + ".bias", as_vector(t.bias));
  write_values(out, p + ".sensitivity", row_major(t.sensitivity));
  write_values(out, p + ".second_order", as_vector(t.second_order));
  write_values(out, p + ".bias_temp", as_vector(t.bias_temp));
  write_values(out, p + ".scale_temp", as_vector(t.scale_temp));
  if (!version2) return;
  write_values(out, p + ".bias_temp2", as_vector(t.bias_temp2));
  write_values(out, p + ".bias_temp3", as_vector(t.bias_temp3));
  write_values(out, p + ".sensor_scale_temp1", as_vector(t.sensor_scale_temp1));
  write_values(out, p + ".sensor_scale_temp2", as_vector(t.sensor_scale_temp2));
  write_values(out, p + ".sensor_scale_temp3", as_vector(t.sensor_scale_temp3));
}

bool is_version2_field(const std::string& field) {
  return field == "bias_temp2" || field == "bias_temp3" || field.rfind("sensor_scale_temp", 0) == 0;
}

// Ids are the rest of their line: a '#' would start a comment and a line break end the value, and
// surrounding blanks are trimmed on reading.
std::string text_value(std::string s) {
  for (char& c : s)
    if (c == '#' || c == '\n' || c == '\r') c = '_';
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// Parses one line's values and reports problems with the file name and line number.
class LineParser {
 public:
  LineParser(const std::string& source, int line_no, std::string key, std::string rest)
      : source_(source), line_no_(line_no), key_(std::move(key)), rest_(std::move(rest)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(source_ + ":" + std::to_string(line_no_) + ": " + what);
  }

  std::vector<double> numbers(std::size_t expected) const {
    std::vector<double> out;
    std::istringstream in(rest_);
    std::string token;
    while (in >> token) {
      const auto x = parse_number(token, true);
      if (!x) fail("'" + key_ + "': '" + token + "' is not a number");
      if (!std::isfinite(*x)) fail("'" + key_ + "': value '" + token + "' is not finite");
      out.push_back(*x);
    }
    if (out.size() != expected)
      fail("'" + key_ + "' needs " + std::to_string(expected) + " values, got " + std::to_string(out.size()));
    return out;
  }

  Eigen::Vector3d vector3() const {
    const auto v = numbers(3);
    return {v[0], v[1], v[2]};
  }

  Eigen::Matrix3d matrix3() const {
    const auto v = numbers(9);
    Eigen::Matrix3d m;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m(r, c) = v[static_cast<std::size_t>(3 * r + c)];
    return m;
  }

  double number() const { return numbers(1)[0]; }
  const std::string& text() const { return rest_; }

 private:
  const std::string& source_;
  int line_no_;
  std::string key_;
  std::string rest_;
};

bool parse_triad_key(const std::string& key, const LineParser& p, const std::string& prefix, TriadModel& t) {
  if (key.rfind(prefix + ".", 0) != 0) return false;
  const std::string field = key.substr(prefix.size() + 1);
  if (field == "bias") t.bias = p.vector3();
  else if (field == "sensitivity") t.sensitivity = p.matrix3();
  else if (field == "second_order") t.second_order = p.vector3();
  else if (field == "bias_temp") t.bias_temp = p.vector3();
  else if (field == "scale_temp") t.scale_temp = p.vector3();
  else if (field == "bias_temp2") t.bias_temp2 = p.vector3();
  else if (field == "bias_temp3") t.bias_temp3 = p.vector3();
  else if (field == "sensor_scale_temp1") t.sensor_scale_temp1 = p.vector3();
  else if (field == "sensor_scale_temp2") t.sensor_scale_temp2 = p.vector3();
  else if (field == "sensor_scale_temp3") t.sensor_scale_temp3 = p.vector3();
  else return false;
  return true;
}

}  // namespace

void write_calibration(std::ostream& out, const CalibrationModel& m) {
  const int version = m.format_version();
  out << "# plumb calibration coefficients (docs/calibration.md)\n";
  if (version == 2)
    out << "# per triad, d = T - T0: s = 1 + sensor_scale_temp1 d + sensor_scale_temp2 d^2 + sensor_scale_temp3 d^3;\n"
        << "# v = u ./ s - (bias + bias_temp d + bias_temp2 d^2 + bias_temp3 d^3); w = diag(1 + scale_temp d) S v;\n";
  else
    out << "# per triad: v = u - (bias + bias_temp (T - T0)); w = diag(1 + scale_temp (T - T0)) S v;\n";
  out
      << "# a solves a + second_order .* a^2 = w; T = c0 + c1 t + c2 t^2 + c3 t^3 (thermometer)\n"
      << "# sensitivity S is 9 values, row-major. accel.*: raw units -> m/s^2 specific force;\n"
      << "# mag.*: raw units -> microtesla.\n";
  out << "format " << kFormatName << ' ' << version << '\n';
  out << "tool_id " << text_value(m.tool_id) << '\n';
  out << "calibration_id " << text_value(m.calibration_id) << '\n';
  if (!m.accel_units.empty()) out << "accel_units " << text_value(m.accel_units) << '\n';
  if (!m.mag_units.empty()) out << "mag_units " << text_value(m.mag_units) << '\n';
  write_values(out, "stamp_s", std::vector<double>{m.stamp_s});
  write_values(out, "reference_temp_c", std::vector<double>{m.reference_temp_c});
  write_values(out, "temp_range_c", std::vector<double>{m.temp_min_c, m.temp_max_c});
  write_values(out, "thermometer", m.thermometer);
  write_triad(out, "accel", m.accelerometer, version == 2);
  write_triad(out, "mag", m.magnetometer, version == 2);
}

CalibrationModel parse_calibration(std::istream& in, const std::string& source) {
  CalibrationModel m;
  std::map<std::string, int> seen;  // key -> line where it was first given
  int version = 0;                  // 0: no format line (every key accepted)
  int first_v2_line = 0;            // a version-2 key in a file that says version 1 is an error
  std::string first_v2_key;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const auto hash = line.find('#');
    const std::string content = trim(std::string_view(line).substr(0, hash));
    if (content.empty()) continue;
    const auto space = content.find_first_of(" \t");
    const std::string key = content.substr(0, space);
    const std::string rest = space == std::string::npos ? std::string() : trim(content.substr(space));
    const LineParser p(source, line_no, key, rest);
    if (const auto [it, fresh] = seen.emplace(key, line_no); !fresh)
      p.fail("'" + key + "' given twice (first on line " + std::to_string(it->second) + ")");

    if (key == "format") {
      std::istringstream words(rest);
      std::string name, extra;
      if (!(words >> name >> version) || (words >> extra) || name != kFormatName)
        p.fail("expected 'format " + std::string(kFormatName) + " 1' or '... 2'");
      if (version < 1 || version > kNewestVersion)
        p.fail("format version " + std::to_string(version) + " is not supported (this build reads 1 and " +
               std::to_string(kNewestVersion) + ")");
    } else if (key == "tool_id") {
      m.tool_id = p.text();
    } else if (key == "calibration_id") {
      m.calibration_id = p.text();
    } else if (key == "accel_units" || key == "mag_units") {
      // One word: units are compared as written ("m/s2" is not "m/s^2").
      if (p.text().empty() || p.text().find_first_of(" \t") != std::string::npos)
        p.fail("'" + key + "' needs one word (e.g. m/s2, V, uT, counts)");
      (key == "accel_units" ? m.accel_units : m.mag_units) = p.text();
    } else if (key == "stamp_s") {
      m.stamp_s = p.number();
    } else if (key == "reference_temp_c") {
      m.reference_temp_c = p.number();
    } else if (key == "temp_range_c") {
      const auto v = p.numbers(2);
      if (!(v[0] < v[1])) p.fail("'temp_range_c' needs min < max");
      m.temp_min_c = v[0];
      m.temp_max_c = v[1];
    } else if (key == "thermometer") {
      const auto v = p.numbers(4);
      for (std::size_t i = 0; i < 4; ++i) m.thermometer[i] = v[i];
    } else if (!parse_triad_key(key, p, "accel", m.accelerometer) &&
               !parse_triad_key(key, p, "mag", m.magnetometer)) {
      p.fail("unknown key '" + key + "'");
    } else if (const auto dot = key.find('.'); is_version2_field(key.substr(dot + 1)) && first_v2_line == 0) {
      first_v2_line = line_no;
      first_v2_key = key;
    }
  }
  // Keys come in any order, so the version is checked once the whole file is read.
  if (version == 1 && first_v2_line > 0)
    throw std::runtime_error(source + ":" + std::to_string(first_v2_line) + ": '" + first_v2_key +
                             "' is a version-2 term but the file says 'format " + std::string(kFormatName) + " 1'");
  if (in.bad()) throw std::runtime_error(source + ": read error");
  if (seen.empty()) throw std::runtime_error(source + ": no calibration coefficients in the file");
  return m;
}

CalibrationModel read_calibration_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open calibration file");
  return parse_calibration(in, path);
}

}  // namespace plumb::csv
