#include "plumb/csv/files.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>

#include "plumb/core/number.hpp"
#include "plumb/core/trim.hpp"

namespace plumb::csv {
namespace {

std::string describe(const std::string& source, std::size_t line, const std::string& column, const std::string& what) {
  std::string s = source + ":" + std::to_string(line) + ": ";
  if (!column.empty()) s += "column '" + column + "': ";
  return s + what;
}

// RFC 4180 within one line: a field whose first non-blank character is '"' runs to the next lone
// '"'; anything between that and the comma is kept (lenient, as spreadsheets are).
std::vector<std::string> split_quoted(const std::string& line) {
  std::vector<std::string> fields;
  const std::size_t n = line.size();
  std::size_t i = 0;
  while (true) {
    const std::size_t start = i;
    while (i < n && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::string field;
    if (i < n && line[i] == '"') {
      for (++i; i < n; ++i) {
        if (line[i] != '"') {
          field += line[i];
        } else if (i + 1 < n && line[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          ++i;
          break;
        }
      }
      const auto comma = std::min(line.find(',', i), n);
      field += trim(line.substr(i, comma - i));
      i = comma;
    } else {
      const auto comma = std::min(line.find(',', start), n);
      field = trim(line.substr(start, comma - start));
      i = comma;
    }
    fields.push_back(field);
    if (i >= n) break;
    ++i;
  }
  return fields;
}

bool is_skippable(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#';
}

// A field is one number, blanks around it allowed (other loggers write "1.0, 2.0"); "nan" and
// "inf" parse here and are counted as bad samples later.
bool parse_double(const std::string& field, double& out) {
  const auto first = field.find_first_not_of(" \t");
  if (first == std::string::npos) return false;
  const auto last = field.find_last_not_of(" \t\r");
  const auto v = parse_number(std::string_view(field).substr(first, last - first + 1), true);
  if (v) out = *v;
  return v.has_value();
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

// A value of an estimate: NaN, what the estimate did not measure, is an empty cell. (A sample's
// NaN is a broken reading, flagged NOT_FINITE, and stays "nan".)
void write_estimated(std::ostream& out, double v) {
  if (!std::isnan(v)) write_number(out, v);
}

}  // namespace

Error::Error(const std::string& src, std::size_t ln, const std::string& col, const std::string& what)
    : std::runtime_error(describe(src, ln, col, what)), source(src), line(ln), column(col) {}

std::vector<std::string> split_line(const std::string& line) {
  if (line.find('"') != std::string::npos) return split_quoted(line);
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
}

SensorReader::SensorReader(std::istream& in, std::string source_name, const Import& import)
    : in_(in), source_(std::move(source_name)), import_(import), convert_(!is_default(import)) {
  std::string line;
  while (std::getline(in_, line)) {
    ++line_;
    if (line_ == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 BOM
    if (is_skippable(line)) continue;
    names_ = split_line(line);
    columns_ = names_.size();
    std::vector<std::string> unmatched;  // "wx='Gyro X'" for each mapping the header lacks
    std::string first_unmatched;         // the first of them in full, with the nearest names
    auto find = [&](const std::string& name) {
      const auto mapped = import_.columns.find(name);
      const std::string& header = mapped == import_.columns.end() ? name : mapped->second;
      const auto it = std::find(names_.begin(), names_.end(), header);
      if (it != names_.end()) return static_cast<int>(it - names_.begin());
      if (mapped != import_.columns.end()) {
        if (unmatched.empty()) {
          first_unmatched = "column '" + name + "': mapped to '" + header + "', which the header lacks";
          std::string near;
          for (const auto& c : closest_names(header, names_)) near += (near.empty() ? "'" : ", '") + c + "'";
          if (!near.empty()) first_unmatched += " (closest: " + near + ")";
        }
        unmatched.push_back(name + "='" + header + "'");
      }
      return -1;
    };
    col_t_ = find("t");
    col_seq_ = find("seq");
    col_temp_ = find("temp_c");
    col_depth_ = find("depth_m");
    const char* fn[3] = {"fx", "fy", "fz"};
    const char* bn[3] = {"bx", "by", "bz"};
    const char* wn[3] = {"wx", "wy", "wz"};
    for (int i = 0; i < 3; ++i) {
      col_f_[i] = find(fn[i]);
      col_b_[i] = find(bn[i]);
      col_w_[i] = find(wn[i]);
    }
    if (!unmatched.empty()) {
      std::string what = first_unmatched;
      if (unmatched.size() > 1) {
        what += "; also missing:";
        for (std::size_t k = 1; k < unmatched.size(); ++k) what += " " + unmatched[k];
      }
      throw Error(source_, line_, "", what);
    }
    std::string missing;
    auto require = [&](int col, const char* name) {
      if (col < 0) missing += (missing.empty() ? "" : ", ") + std::string(name);
    };
    require(col_t_, "t");
    for (int i = 0; i < 3; ++i) require(col_f_[i], fn[i]);
    if (!missing.empty()) {
      throw Error(source_, line_, "",
                  "header lacks required column(s) " + missing +
                      (import_.columns.empty() ? "" : " (map them with --column NAME=\"HEADER TEXT\")"));
    }
    const int mag_cols = (col_b_[0] >= 0) + (col_b_[1] >= 0) + (col_b_[2] >= 0);
    if (mag_cols != 0 && mag_cols != 3) {
      for (int i = 0; i < 3; ++i) require(col_b_[i], bn[i]);
      throw Error(source_, line_, "", "header lacks " + missing + ": bx, by, bz come all three or none");
    }
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
    if (has_magnetometer()) {
      for (int i = 0; i < 3; ++i) s.b[i] = get(col_b_[i]);
    } else {
      s.flags |= flags::kNoMagnetometer;
    }
    if (has_gyro()) {
      for (int i = 0; i < 3; ++i) s.w[i] = get(col_w_[i]);
      s.flags |= flags::kHasGyro;
    }
    if (has_temperature()) {
      s.temp_c = get(col_temp_);
      s.flags |= flags::kHasTemperature;
    }
    // A rig reports depth about once a second: a logger writes it on the row after each report and
    // leaves the cell empty elsewhere. An empty cell is a row without depth, not a bad number.
    if (has_depth() && !fields[col_depth_].empty()) {
      s.depth_m = get(col_depth_);
      s.flags |= flags::kHasDepth;
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
    if (convert_) {
      s.t *= import_.time.scale;
      s.f = to_tool(import_, s.f * import_.accel.scale);
      s.b = to_tool(import_, s.b * import_.mag.scale);
      s.w = to_tool(import_, s.w * import_.gyro.scale);
      s.depth_m *= import_.depth.scale;
    }
    ++rows_;
    out = s;
    return true;
  }
  return false;
}

std::vector<Sample> read_sensor_file(const std::string& path, const Import& import) {
  std::ifstream in(path);
  if (!in) throw Error(path, 0, "", "cannot open file");
  SensorReader reader(in, path, import);
  std::vector<Sample> samples;
  Sample s;
  while (reader.next(s)) samples.push_back(s);
  return samples;
}

void write_sensor_header(std::ostream& out, bool with_gyro, bool with_temperature, bool with_depth) {
  out << "seq,t,fx,fy,fz,bx,by,bz";
  if (with_gyro) out << ",wx,wy,wz";
  if (with_temperature) out << ",temp_c";
  if (with_depth) out << ",depth_m";
  out << '\n';
}

void write_sensor_row(std::ostream& out, const Sample& s, bool with_gyro, bool with_temperature, bool with_depth) {
  out << s.seq << ',' << std::setprecision(12) << s.t << std::setprecision(10);
  for (int i = 0; i < 3; ++i) out << ',', write_number(out, s.f[i]);
  for (int i = 0; i < 3; ++i) out << ',', write_number(out, s.b[i]);
  if (with_gyro) for (int i = 0; i < 3; ++i) out << ',', write_number(out, s.w[i]);
  if (with_temperature) out << ',', write_number(out, s.temp_c);
  if (with_depth) out << ',', write_number(out, s.depth_m);
  out << '\n';
}

void write_attitude_header(std::ostream& out, bool with_navigation) {
  out << "t,inclination_deg,azimuth_deg,toolface_deg,rpm,valid,";
  if (with_navigation) out << "north_m,east_m,down_m,vn_mps,ve_mps,vd_mps,";
  out << "magnetic_toolface_deg,inclination_sd_deg,"
         "azimuth_sd_deg,toolface_sd_deg,dip_deg,total_g,total_b,samples_used,azimuth_valid,toolface_valid,"
         "estimator,reason";
  if (with_navigation)
    out << ",north_sd_m,east_sd_m,down_sd_m,vn_sd_mps,ve_sd_mps,vd_sd_mps,still,zupt_count,azimuth_reference";
  out << '\n';
}

void write_attitude_row(std::ostream& out, const Estimate& e, bool with_navigation) {
  const NavigationState none;
  const NavigationState& nav = e.navigation ? *e.navigation : none;
  out << std::setprecision(12) << e.t_end << std::setprecision(10);
  for (double v : {e.inclination_deg, e.azimuth_deg, e.gravity_toolface_deg, e.rpm}) out << ',', write_estimated(out, v);
  out << ',' << (e.valid ? 1 : 0);
  if (with_navigation) {
    for (double v : nav.position_m) out << ',', write_estimated(out, v);
    for (double v : nav.velocity_mps) out << ',', write_estimated(out, v);
  }
  for (double v : {e.magnetic_toolface_deg, e.inclination_sd_deg, e.azimuth_sd_deg, e.toolface_sd_deg, e.dip_deg,
                   e.total_g, e.total_b})
    out << ',', write_estimated(out, v);
  out << ',' << e.samples_used << ',' << (e.azimuth_valid ? 1 : 0) << ',' << (e.toolface_valid ? 1 : 0) << ','
      << sanitize(e.estimator) << ',' << sanitize(e.reason);
  if (with_navigation) {
    for (double v : nav.position_sd_m) out << ',', write_estimated(out, v);
    for (double v : nav.velocity_sd_mps) out << ',', write_estimated(out, v);
    out << ',' << (nav.still ? 1 : 0) << ',' << nav.zero_velocity_updates << ',' << sanitize(nav.azimuth_reference);
  }
  out << '\n';
}

void write_truth_header(std::ostream& out, bool with_position) {
  out << "t,inclination_deg,azimuth_deg,toolface_deg,rpm";
  if (with_position) out << ",north_m,east_m,down_m,vn_mps,ve_mps,vd_mps,depth_m";
  out << '\n';
}

void write_truth_row(std::ostream& out, const TruthSample& s, bool with_position) {
  out << std::setprecision(12) << s.t << std::setprecision(10) << ',' << s.inclination_deg << ',' << s.azimuth_deg
      << ',' << s.toolface_deg << ',' << s.rpm;
  if (with_position) {
    for (double v : {s.north_m, s.east_m, s.down_m, s.vn_mps, s.ve_mps, s.vd_mps, s.depth_m})
      out << ',', write_number(out, v);
  }
  out << '\n';
}

std::vector<TruthSample> read_truth_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path, 0, "", "cannot open file");
  std::string line;
  std::size_t ln = 0;
  std::vector<std::string> names;
  std::vector<TruthSample> rows;
  const char* required[5] = {"t", "inclination_deg", "azimuth_deg", "toolface_deg", "rpm"};
  const char* position[7] = {"north_m", "east_m", "down_m", "vn_mps", "ve_mps", "vd_mps", "depth_m"};
  int cols[5];
  int pos_cols[7];
  bool with_position = true;
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
      for (int i = 0; i < 7; ++i) {
        const auto it = std::find(names.begin(), names.end(), position[i]);
        pos_cols[i] = it == names.end() ? -1 : static_cast<int>(it - names.begin());
        with_position = with_position && pos_cols[i] >= 0;
      }
      continue;
    }
    const auto f = split_line(line);
    double v[5];
    for (int i = 0; i < 5; ++i) {
      if (cols[i] >= static_cast<int>(f.size()) || !parse_double(f[cols[i]], v[i]))
        throw Error(path, ln, required[i], "bad or missing number");
    }
    TruthSample row{v[0], v[1], v[2], v[3], v[4]};
    if (with_position) {
      double p[7];
      for (int i = 0; i < 7; ++i) {
        if (pos_cols[i] >= static_cast<int>(f.size()) || !parse_double(f[pos_cols[i]], p[i]))
          throw Error(path, ln, position[i], "bad or missing number");
      }
      row.has_position = true;
      row.north_m = p[0], row.east_m = p[1], row.down_m = p[2];
      row.vn_mps = p[3], row.ve_mps = p[4], row.vd_mps = p[5], row.depth_m = p[6];
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace plumb::csv
