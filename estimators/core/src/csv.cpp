#include "plumb/core/csv.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>

namespace plumb::csv {
namespace {

std::string describe(const std::string& source, std::size_t line, const std::string& column, const std::string& what) {
  std::string s = source + ":" + std::to_string(line) + ": ";
  if (!column.empty()) s += "column '" + column + "': ";
  return s + what;
}

bool is_skippable(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#';
}

// Strict number parse: the whole field must be a number ("nan"/"inf" allowed, flagged later).
bool parse_double(const std::string& field, double& out) {
  if (field.empty()) return false;
  errno = 0;
  char* end = nullptr;
  out = std::strtod(field.c_str(), &end);
  return end == field.c_str() + field.size() && errno != ERANGE;
}

std::string sanitize(std::string text) {
  std::replace(text.begin(), text.end(), ',', ';');
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

void write_number(std::ostream& out, double v) {
  if (std::isfinite(v)) {
    out << v;
  } else {
    out << (std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf"));
  }
}

}  // namespace

Error::Error(const std::string& src, std::size_t ln, const std::string& col, const std::string& what)
    : std::runtime_error(describe(src, ln, col, what)), source(src), line(ln), column(col) {}

std::vector<std::string> split_line(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    std::string f = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto b = f.find_first_not_of(" \t\r");
    const auto e = f.find_last_not_of(" \t\r");
    fields.push_back(b == std::string::npos ? std::string() : f.substr(b, e - b + 1));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
}

SensorReader::SensorReader(std::istream& in, std::string source_name) : in_(in), source_(std::move(source_name)) {
  std::string line;
  while (std::getline(in_, line)) {
    ++line_;
    if (line_ == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 BOM
    if (is_skippable(line)) continue;
    names_ = split_line(line);
    columns_ = names_.size();
    auto find = [&](const char* name) {
      const auto it = std::find(names_.begin(), names_.end(), name);
      return it == names_.end() ? -1 : static_cast<int>(it - names_.begin());
    };
    col_t_ = find("t");
    col_seq_ = find("seq");
    col_temp_ = find("temp_c");
    const char* fn[3] = {"fx", "fy", "fz"};
    const char* bn[3] = {"bx", "by", "bz"};
    const char* wn[3] = {"wx", "wy", "wz"};
    for (int i = 0; i < 3; ++i) {
      col_f_[i] = find(fn[i]);
      col_b_[i] = find(bn[i]);
      col_w_[i] = find(wn[i]);
    }
    std::string missing;
    auto require = [&](int col, const char* name) {
      if (col < 0) missing += (missing.empty() ? "" : ", ") + std::string(name);
    };
    require(col_t_, "t");
    for (int i = 0; i < 3; ++i) require(col_f_[i], fn[i]);
    for (int i = 0; i < 3; ++i) require(col_b_[i], bn[i]);
    if (!missing.empty()) throw Error(source_, line_, "", "header lacks required column(s) " + missing);
    const int gyro_cols = (col_w_[0] >= 0) + (col_w_[1] >= 0) + (col_w_[2] >= 0);
    if (gyro_cols != 0 && gyro_cols != 3) throw Error(source_, line_, "", "header names some but not all of wx, wy, wz");
    return;
  }
  throw Error(source_, line_, "", "no header line (empty file)");
}

bool SensorReader::next(Sample& out) {
  std::string line;
  while (std::getline(in_, line)) {
    ++line_;
    if (is_skippable(line)) continue;
    const auto fields = split_line(line);
    if (fields.size() < columns_) {
      throw Error(source_, line_, fields.size() < names_.size() ? names_[fields.size()] : "",
                  "row has " + std::to_string(fields.size()) + " fields, header has " + std::to_string(columns_));
    }
    Sample s;
    bool finite = true;
    auto get = [&](int col) {
      double v = 0;
      if (!parse_double(fields[col], v)) throw Error(source_, line_, names_[col], "bad number '" + fields[col] + "'");
      finite = finite && std::isfinite(v);
      return v;
    };
    s.t = get(col_t_);
    for (int i = 0; i < 3; ++i) s.f[i] = get(col_f_[i]);
    for (int i = 0; i < 3; ++i) s.b[i] = get(col_b_[i]);
    if (has_gyro()) {
      for (int i = 0; i < 3; ++i) s.w[i] = get(col_w_[i]);
      s.flags |= flags::kHasGyro;
    }
    if (has_temperature()) {
      s.temp_c = get(col_temp_);
      s.flags |= flags::kHasTemperature;
    }
    if (col_seq_ >= 0) {
      const double seq = get(col_seq_);
      // 2^64 and above would overflow the conversion (undefined behaviour; found by fuzzing).
      if (!(seq >= 0) || seq != std::floor(seq) || seq >= 18446744073709551616.0)
        throw Error(source_, line_, "seq", "not a non-negative integer");
      s.seq = static_cast<std::uint64_t>(seq);
    } else {
      s.seq = rows_;
    }
    if (!finite) s.flags |= flags::kNotFinite;
    ++rows_;
    out = s;
    return true;
  }
  return false;
}

std::vector<Sample> read_sensor_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path, 0, "", "cannot open file");
  SensorReader reader(in, path);
  std::vector<Sample> samples;
  Sample s;
  while (reader.next(s)) samples.push_back(s);
  return samples;
}

void write_sensor_header(std::ostream& out, bool with_gyro, bool with_temperature) {
  out << "seq,t,fx,fy,fz,bx,by,bz";
  if (with_gyro) out << ",wx,wy,wz";
  if (with_temperature) out << ",temp_c";
  out << '\n';
}

void write_sensor_row(std::ostream& out, const Sample& s, bool with_gyro, bool with_temperature) {
  out << s.seq << ',' << std::setprecision(12) << s.t << std::setprecision(10);
  for (int i = 0; i < 3; ++i) out << ',', write_number(out, s.f[i]);
  for (int i = 0; i < 3; ++i) out << ',', write_number(out, s.b[i]);
  if (with_gyro) for (int i = 0; i < 3; ++i) out << ',', write_number(out, s.w[i]);
  if (with_temperature) out << ',', write_number(out, s.temp_c);
  out << '\n';
}

void write_attitude_header(std::ostream& out) {
  out << "t,inclination_deg,azimuth_deg,toolface_deg,rpm,valid,magnetic_toolface_deg,inclination_sd_deg,"
         "azimuth_sd_deg,toolface_sd_deg,dip_deg,total_g,total_b,samples_used,azimuth_valid,toolface_valid,"
         "estimator,reason\n";
}

void write_attitude_row(std::ostream& out, const Estimate& e) {
  out << std::setprecision(12) << e.t_end << std::setprecision(10);
  for (double v : {e.inclination_deg, e.azimuth_deg, e.gravity_toolface_deg, e.rpm}) out << ',', write_number(out, v);
  out << ',' << (e.valid ? 1 : 0);
  for (double v : {e.magnetic_toolface_deg, e.inclination_sd_deg, e.azimuth_sd_deg, e.toolface_sd_deg, e.dip_deg,
                   e.total_g, e.total_b})
    out << ',', write_number(out, v);
  out << ',' << e.samples_used << ',' << (e.azimuth_valid ? 1 : 0) << ',' << (e.toolface_valid ? 1 : 0) << ','
      << sanitize(e.estimator) << ',' << sanitize(e.reason) << '\n';
}

void write_truth_header(std::ostream& out) { out << "t,inclination_deg,azimuth_deg,toolface_deg,rpm\n"; }

void write_truth_row(std::ostream& out, const TruthSample& s) {
  out << std::setprecision(12) << s.t << std::setprecision(10) << ',' << s.inclination_deg << ',' << s.azimuth_deg
      << ',' << s.toolface_deg << ',' << s.rpm << '\n';
}

std::vector<TruthSample> read_truth_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path, 0, "", "cannot open file");
  std::string line;
  std::size_t ln = 0;
  std::vector<std::string> names;
  std::vector<TruthSample> rows;
  const char* required[5] = {"t", "inclination_deg", "azimuth_deg", "toolface_deg", "rpm"};
  int cols[5];
  while (std::getline(in, line)) {
    ++ln;
    if (is_skippable(line)) continue;
    if (names.empty()) {
      names = split_line(line);
      for (int i = 0; i < 5; ++i) {
        const auto it = std::find(names.begin(), names.end(), required[i]);
        if (it == names.end()) throw Error(path, ln, "", std::string("header lacks column ") + required[i]);
        cols[i] = static_cast<int>(it - names.begin());
      }
      continue;
    }
    const auto f = split_line(line);
    double v[5];
    for (int i = 0; i < 5; ++i) {
      if (cols[i] >= static_cast<int>(f.size()) || !parse_double(f[cols[i]], v[i]))
        throw Error(path, ln, required[i], "bad or missing number");
    }
    rows.push_back({v[0], v[1], v[2], v[3], v[4]});
  }
  return rows;
}

}  // namespace plumb::csv
