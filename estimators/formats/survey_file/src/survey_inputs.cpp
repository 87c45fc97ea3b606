#include "plumb/survey/survey_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

#include "plumb/core/number.hpp"
#include "plumb/csv/files.hpp"

namespace plumb::survey {
namespace {

// A CSV with named columns: required ones must be in the header, optional ones may be.
class Table {
 public:
  Table(const std::string& path, const std::vector<std::string>& required) : path_(path), in_(path) {
    if (!in_) throw std::runtime_error("cannot open '" + path + "'");
    std::string line;
    while (std::getline(in_, line)) {
      ++line_no_;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty() || line[0] == '#') continue;
      const auto names = csv::split_line(line);
      for (std::size_t i = 0; i < names.size(); ++i) columns_[names[i]] = i;
      break;
    }
    for (const auto& r : required)
      if (!columns_.count(r)) throw std::runtime_error(path + ": no column '" + r + "' in the header");
  }
  bool next() {
    std::string line;
    while (std::getline(in_, line)) {
      ++line_no_;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty() || line[0] == '#') continue;
      fields_ = csv::split_line(line);
      return true;
    }
    return false;
  }
  bool has(const std::string& name) const { return columns_.count(name) > 0; }
  std::string text(const std::string& name) const {
    const auto it = columns_.find(name);
    return it == columns_.end() || it->second >= fields_.size() ? std::string() : fields_[it->second];
  }
  double number(const std::string& name) const {
    const std::string t = text(name);
    const auto v = parse_number(t, true);
    if (!v) throw std::runtime_error(where() + "column '" + name + "': bad number '" + t + "'");
    if (!std::isfinite(*v)) throw std::runtime_error(where() + "column '" + name + "': not a finite number ('" + t + "')");
    return *v;
  }
  std::optional<double> optional(const std::string& name) const {
    if (!has(name)) return std::nullopt;
    return number(name);
  }
  // A value an estimate may not have measured: an empty cell (or a missing column) is NaN.
  double measured(const std::string& name) const {
    const std::string t = text(name);
    if (t.empty()) return std::numeric_limits<double>::quiet_NaN();
    const auto v = parse_number(t, true);
    if (!v) throw std::runtime_error(where() + "column '" + name + "': bad number '" + t + "'");
    return *v;
  }
  std::string where() const { return path_ + ":" + std::to_string(line_no_) + ": "; }

 private:
  std::string path_;
  std::ifstream in_;
  std::size_t line_no_ = 0;
  std::map<std::string, std::size_t> columns_;
  std::vector<std::string> fields_;
};

}  // namespace

std::vector<Estimate> read_attitude_csv(const std::string& path, double window_s) {
  Table t(path, {"t", "inclination_deg", "azimuth_deg", "valid"});
  std::vector<Estimate> out;
  while (t.next()) {
    Estimate e;
    e.t_end = t.number("t");
    e.inclination_deg = t.measured("inclination_deg");
    e.azimuth_deg = t.measured("azimuth_deg");
    e.valid = t.number("valid") != 0;
    e.azimuth_valid = t.has("azimuth_valid") ? t.number("azimuth_valid") != 0 : e.valid;
    e.inclination_sd_deg = t.measured("inclination_sd_deg");
    e.azimuth_sd_deg = t.measured("azimuth_sd_deg");
    e.dip_deg = t.measured("dip_deg");
    e.total_g = t.measured("total_g");
    e.total_b = t.measured("total_b");
    e.rpm = t.optional("rpm").value_or(0);
    e.rotating = std::abs(e.rpm) >= 1;
    e.estimator = t.has("estimator") ? t.text("estimator") : "attitude-csv";
    if (!out.empty() && e.t_end <= out.back().t_end)
      throw std::runtime_error(t.where() + "time " + t.text("t") + " s does not increase");
    out.push_back(e);
  }
  if (out.empty()) throw std::runtime_error(path + ": no attitude rows");
  double w = window_s;
  if (w <= 0) {
    std::vector<double> gaps;
    for (std::size_t k = 1; k < out.size(); ++k) gaps.push_back(out[k].t_end - out[k - 1].t_end);
    if (gaps.empty()) throw std::runtime_error(path + ": one attitude row: give --window");
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
    w = gaps[gaps.size() / 2];
  }
  for (auto& e : out) e.t_start = e.t_end - w;
  return out;
}

std::vector<DepthReport> read_depth_csv(const std::string& path) {
  Table t(path, {"t", "depth_m"});
  std::vector<DepthReport> out;
  while (t.next()) {
    DepthReport d;
    d.t_s = t.number("t");
    d.depth_m = t.number("depth_m");
    d.sd_m = t.optional("depth_sd_m").value_or(0);
    if (!out.empty() && d.t_s <= out.back().t_s) throw std::runtime_error(t.where() + "time " + t.text("t") + " s does not increase");
    out.push_back(d);
  }
  if (out.empty()) throw std::runtime_error(path + ": no depth rows");
  return out;
}

std::vector<Station> read_station_csv(const std::string& path) {
  Table t(path, {"md_m", "inclination_deg", "azimuth_deg"});
  std::vector<Station> out;
  while (t.next()) {
    Station s;
    s.source = path;
    s.md_m = t.number("md_m");
    s.inclination_deg = t.number("inclination_deg");
    s.magnetic_azimuth_deg = t.number("azimuth_deg");
    s.md_sd_m = t.optional("md_sd_m").value_or(0);
    s.inclination_sd_deg = t.optional("inclination_sd_deg").value_or(0);
    s.azimuth_sd_deg = t.optional("azimuth_sd_deg").value_or(0);
    if (auto v = t.optional("total_g_mps2")) s.total_g_mps2 = *v;
    if (auto v = t.optional("total_b_uT")) s.total_b_uT = *v;
    if (auto v = t.optional("dip_deg")) s.dip_deg = *v;
    s.t_s = t.optional("t").value_or(0);
    if (s.inclination_deg < 0 || s.inclination_deg > 180)
      throw std::runtime_error(t.where() + "inclination " + t.text("inclination_deg") + " deg outside [0, 180]");
    if (s.magnetic_azimuth_deg < 0 || s.magnetic_azimuth_deg >= 360)
      throw std::runtime_error(t.where() + "azimuth " + t.text("azimuth_deg") + " deg outside [0, 360)");
    out.push_back(s);
  }
  if (out.empty()) throw std::runtime_error(path + ": no station rows");
  return out;
}

}  // namespace plumb::survey
