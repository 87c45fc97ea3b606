#include "plumb/csv/import.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <stdexcept>

#include "plumb/core/edit_distance.hpp"
#include "plumb/core/number.hpp"
#include "plumb/core/trim.hpp"

namespace plumb::csv {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

struct UnitName {
  const char* name;
  double scale;
};

// Several spellings per unit: people type m/s^2, loggers write m/s² and µT (U+00B5 or U+03BC).
const std::vector<UnitName> kAccel = {
    {"m/s2", 1.0}, {"m/s^2", 1.0}, {"m/s\xC2\xB2", 1.0}, {"g", 9.80665}, {"mg", 9.80665e-3}};
const std::vector<UnitName> kGyro = {{"rad/s", 1.0}, {"deg/s", kDegree}, {"dps", kDegree}, {"\xC2\xB0/s", kDegree}};
const std::vector<UnitName> kMag = {{"uT", 1.0},  {"\xC2\xB5T", 1.0}, {"\xCE\xBCT", 1.0},
                                    {"nT", 1e-3}, {"mT", 1e3},        {"gauss", 100.0}};
const std::vector<UnitName> kTime = {{"s", 1.0}, {"ms", 1e-3}, {"us", 1e-6}, {"\xC2\xB5s", 1e-6}, {"ns", 1e-9}};
const std::vector<UnitName> kDepth = {{"m", 1.0}, {"ft", 0.3048}};

std::string join(const std::vector<std::string>& items, const char* sep = ", ") {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : sep) + s;
  return out;
}

std::string accepted(const std::vector<UnitName>& table) {
  std::vector<std::string> names;
  for (const auto& u : table) names.emplace_back(u.name);
  return join(names);
}

std::vector<std::string> split_on(const std::string& text, const std::string& separators) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : text) {
    if (separators.find(c) != std::string::npos) {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

const std::string kAxesUsage =
    "--axes: expected a signed permutation such as x,-y,-z (tool x = sensor x, tool y = -sensor y, ...) or nine "
    "numbers r11 r12 r13 r21 r22 r23 r31 r32 r33 (row i = tool axis i in sensor axes)";

}  // namespace

const std::vector<std::string>& Import::plumb_columns() {
  static const std::vector<std::string> names = {"t",  "seq", "fx", "fy", "fz", "bx",     "by",
                                                 "bz", "wx",  "wy", "wz", "temp_c", "depth_m"};
  return names;
}

void add_column(Import& import, const std::string& spec) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos)
    throw std::invalid_argument("--column: expected NAME=HEADER (e.g. wx=\"Gyroscope X (deg/s)\"), got '" + spec + "'");
  const std::string name = trim(spec.substr(0, eq));
  std::string header = trim(spec.substr(eq + 1));
  // The shell usually eats the quotes; when they reach us (a quoted header in a script), drop them.
  if (header.size() >= 2 && header.front() == '"' && header.back() == '"') {
    std::string inner;
    for (std::size_t i = 1; i + 1 < header.size(); ++i) {
      inner += header[i];
      if (header[i] == '"' && header[i + 1] == '"') ++i;
    }
    header = inner;
  }
  const auto& known = Import::plumb_columns();
  if (std::find(known.begin(), known.end(), name) == known.end())
    throw std::invalid_argument("--column: '" + name + "' is not a plumb column (accepted: " + join(known) + ")");
  if (header.empty()) throw std::invalid_argument("--column " + name + "=: the header text is empty");
  if (import.columns.count(name))
    throw std::invalid_argument("--column: " + name + " is mapped twice ('" + import.columns[name] + "' and '" +
                                header + "')");
  for (const auto& [other, text] : import.columns) {
    if (text == header)
      throw std::invalid_argument("--column: '" + header + "' is mapped to both " + other + " and " + name);
  }
  import.columns[name] = header;
}

void add_units(Import& import, const std::string& spec) {
  for (const auto& raw : split_on(spec, ",")) {
    const std::string item = trim(raw);
    if (item.empty()) continue;
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument("--units: expected GROUP=UNIT (e.g. accel=g,gyro=deg/s,mag=gauss), got '" + item + "'");
    const std::string group = trim(item.substr(0, eq));
    const std::string unit = trim(item.substr(eq + 1));
    const std::vector<UnitName>* table = nullptr;
    Unit* target = nullptr;
    if (group == "accel") table = &kAccel, target = &import.accel;
    if (group == "gyro") table = &kGyro, target = &import.gyro;
    if (group == "mag") table = &kMag, target = &import.mag;
    if (group == "time") table = &kTime, target = &import.time;
    if (group == "depth") table = &kDepth, target = &import.depth;
    if (!table)
      throw std::invalid_argument("--units: unknown group '" + group + "' (accepted: accel, gyro, mag, time, depth)");
    const auto it = std::find_if(table->begin(), table->end(), [&](const UnitName& u) { return unit == u.name; });
    if (it == table->end())
      throw std::invalid_argument("--units: unknown " + group + " unit '" + unit + "' (accepted: " + accepted(*table) + ")");
    *target = Unit{it->name, it->scale};
  }
}

void set_axes(Import& import, const std::string& spec) {
  const std::string text = trim(spec);
  if (text.empty()) {
    import.axes = Eigen::Matrix3d::Identity();
    import.axes_text = "x,y,z";
    return;
  }
  const auto tokens = split_on(text, ", \t;");
  const bool letters = std::any_of(tokens.begin(), tokens.end(), [](const std::string& t) {
    return t.find_first_of("xyzXYZ") != std::string::npos;
  });
  Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
  std::string normalized;
  if (letters) {
    if (tokens.size() != 3) throw std::invalid_argument(kAxesUsage + ", got '" + text + "'");
    bool used[3] = {false, false, false};
    for (int i = 0; i < 3; ++i) {
      std::string t = tokens[static_cast<std::size_t>(i)];
      double sign = 1;
      if (!t.empty() && (t[0] == '-' || t[0] == '+')) {
        sign = t[0] == '-' ? -1 : 1;
        t.erase(0, 1);
      }
      const auto pos = t.size() == 1 ? std::string("xyz").find(static_cast<char>(std::tolower(t[0]))) : std::string::npos;
      if (pos == std::string::npos) throw std::invalid_argument(kAxesUsage + ", got '" + text + "'");
      const int axis = static_cast<int>(pos);
      if (used[axis])
        throw std::invalid_argument("--axes '" + text + "': sensor axis " + std::string(1, "xyz"[axis]) +
                                    " is used twice; each of x, y, z once");
      used[axis] = true;
      r(i, axis) = sign;
      normalized += std::string(i ? "," : "") + (sign < 0 ? "-" : "") + "xyz"[axis];
    }
  } else {
    if (tokens.size() != 9) throw std::invalid_argument(kAxesUsage + ", got '" + text + "'");
    for (int k = 0; k < 9; ++k) {
      const std::string& t = tokens[static_cast<std::size_t>(k)];
      const auto v = parse_number(t);
      if (!v) throw std::invalid_argument("--axes: '" + t + "' is not a number; " + kAxesUsage.substr(8));
      r(k / 3, k % 3) = *v;
    }
    const double off = (r * r.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (off > 1e-6)
      throw std::invalid_argument("--axes '" + text + "': not a rotation (rows not orthonormal within 1e-6; off by " +
                                  std::to_string(off) + ")");
    normalized = text;
  }
  if (std::abs(r.determinant() - 1) > 1e-6)
    throw std::invalid_argument("--axes '" + text +
                                "': a reflection (determinant -1); sensor and tool frames are right-handed "
                                "(docs/conventions.md), so flip an even number of axes or swap two axes and flip one");
  import.axes = r;
  import.axes_text = normalized;
}

Import make_import(const std::vector<std::string>& columns, const std::vector<std::string>& units,
                   const std::string& axes) {
  Import import;
  for (const auto& c : columns) add_column(import, c);
  for (const auto& u : units) add_units(import, u);
  set_axes(import, axes);
  return import;
}

bool is_default(const Import& import) {
  return import.columns.empty() && import.accel.scale == 1 && import.gyro.scale == 1 && import.mag.scale == 1 &&
         import.time.scale == 1 && import.depth.scale == 1 && import.axes == Eigen::Matrix3d::Identity();
}

std::string describe(const Import& import) {
  std::vector<std::string> columns;
  for (const auto& name : Import::plumb_columns()) {
    const auto it = import.columns.find(name);
    if (it != import.columns.end()) columns.push_back(name + "='" + it->second + "'");
  }
  return "columns " + (columns.empty() ? std::string("as named") : join(columns)) + "; units accel=" +
         import.accel.name + ", gyro=" + import.gyro.name + ", mag=" + import.mag.name + ", time=" + import.time.name +
         ", depth=" + import.depth.name + "; axes " + import.axes_text;
}

Eigen::Vector3d to_tool(const Import& import, const Eigen::Vector3d& sensor) {
  Eigen::Vector3d tool = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (import.axes(i, j) != 0) tool[i] += import.axes(i, j) * sensor[j];
    }
  }
  return tool;
}

std::vector<std::string> closest_names(const std::string& wanted, const std::vector<std::string>& names, std::size_t n) {
  std::vector<std::pair<std::size_t, std::size_t>> ranked;  // distance, index
  const std::string w = lower(wanted);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (!names[i].empty()) ranked.emplace_back(edit_distance(w, lower(names[i])), i);
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (std::size_t k = 0; k < ranked.size() && k < n; ++k) out.push_back(names[ranked[k].second]);
  return out;
}

}  // namespace plumb::csv
