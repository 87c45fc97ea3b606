// The tool code file (docs/conventions.md "Tool code file"): an ISCWSA error model's terms.
#include "plumb/survey/tool_code_file.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "plumb/core/number.hpp"
#include "plumb/csv/files.hpp"

namespace plumb::survey::iscwsa {

namespace {

// The gyro model's running (plumb/survey/iscwsa.hpp GyroRunning): "# gyro_static_inc_deg FROM TO",
// "# gyro_continuous_inc_deg FROM TO" (the tool runs continuously from there), "#
// gyro_initialisation gyrocompass|reference", "# gyro_initialisation_inc_deg V", "#
// gyro_running_speed_m_per_h V" (0: the stations' times), "# gyro_noise_reduction_factor V", "#
// gyro_z_drift_inc_deg FROM TO", "# gyro_xy_drift_inc_deg FROM TO".
void read_gyro_key(GyroRunning& g, const std::string& key, const std::string& value, const std::string& second,
                   const std::string& where) {
  const auto number = [&](const std::string& text, bool positive) {
    const auto v = parse_number(text);
    if (!v || !std::isfinite(*v) || *v < 0 || (positive && *v == 0))
      throw std::runtime_error(where + key + ": bad number '" + text + "'");
    return *v;
  };
  if (key == "gyro_static_inc_deg" || key == "gyro_continuous_inc_deg" || key == "gyro_z_drift_inc_deg" ||
      key == "gyro_xy_drift_inc_deg") {
    const double from = number(value, false), to = number(second, false);
    if (!(to >= from && to <= 180)) throw std::runtime_error(where + key + ": FROM TO in degrees, 0 <= FROM <= TO <= 180");
    if (key == "gyro_static_inc_deg") {
      g.static_start_inc_deg = from, g.static_end_inc_deg = to;
    } else if (key == "gyro_continuous_inc_deg") {
      g.continuous = true, g.continuous_start_inc_deg = from, g.continuous_end_inc_deg = to;
    } else if (key == "gyro_z_drift_inc_deg") {
      g.z_drift_from_inc_deg = from, g.z_drift_to_inc_deg = to;
    } else {
      g.xy_drift_from_inc_deg = from, g.xy_drift_to_inc_deg = to;
    }
  } else if (key == "gyro_initialisation") {
    if (value == "gyrocompass") g.initialisation = GyroInitialisation::Gyrocompass;
    else if (value == "reference") g.initialisation = GyroInitialisation::Reference;
    else throw std::runtime_error(where + key + ": '" + value + "' is not gyrocompass or reference");
  } else if (key == "gyro_initialisation_inc_deg") {
    g.initialisation_inc_deg = number(value, false);
  } else if (key == "gyro_running_speed_m_per_h") {
    g.running_speed_m_per_h = number(value, false);
  } else if (key == "gyro_noise_reduction_factor") {
    g.noise_reduction_factor = number(value, true);
  } else {
    throw std::runtime_error(where + "unknown gyro key '" + key + "' (gyro_static_inc_deg, gyro_continuous_inc_deg, "
                             "gyro_initialisation, gyro_initialisation_inc_deg, gyro_running_speed_m_per_h, "
                             "gyro_noise_reduction_factor, gyro_z_drift_inc_deg, gyro_xy_drift_inc_deg)");
  }
}

}  // namespace

ToolCode read_tool_code(std::istream& in, const std::string& source) {
  ToolCode t{source, 5, 0.000572615, {}};
  std::map<std::string, std::size_t> columns;
  std::string line;
  std::size_t line_no = 0;
  const char* required[] = {"code", "weight_function", "magnitude", "unit", "propagation"};
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string where = source + ":" + std::to_string(line_no) + ": ";
    if (line.empty()) continue;
    if (line[0] == '#') {
      std::istringstream words(line.substr(1));
      std::string key, value;
      words >> key >> value;
      if (key == "xy_accelerometer_cant_deg") {
        const auto v = parse_number(value);
        if (!v || !std::isfinite(*v)) throw std::runtime_error(where + key + ": bad number '" + value + "'");
        t.xy_accelerometer_cant_deg = *v;
      } else if (key == "tortuosity_rad_per_m" || key == "revision") {
        const auto v = parse_number(value);
        if (!v || !(*v > 0)) throw std::runtime_error(where + key + ": bad number '" + value + "'");
        if (key == "revision") t.revision = static_cast<int>(*v);
        else t.tortuosity_rad_per_m = *v;
      } else if (key.rfind("gyro_", 0) == 0) {
        std::string second;
        words >> second;
        read_gyro_key(t.gyro, key, value, second, where);
      }
      continue;
    }
    const auto fields = csv::split_line(line);
    if (columns.empty()) {
      for (std::size_t i = 0; i < fields.size(); ++i) columns[fields[i]] = i;
      for (const char* r : required)
        if (!columns.count(r)) throw std::runtime_error(where + "no column '" + r + "' in the header");
      continue;
    }
    const auto get = [&](const char* name) {
      const std::size_t i = columns.at(name);
      return i < fields.size() ? fields[i] : std::string();
    };
    Term term;
    term.code = get("code");
    term.weight_function = get("weight_function");
    term.unit = get("unit");
    const auto m = parse_number(get("magnitude"));
    if (!m || !std::isfinite(*m) || *m < 0) throw std::runtime_error(where + "magnitude: bad number '" + get("magnitude") + "'");
    term.magnitude = *m;
    const std::string p = get("propagation");
    if (p == "R") term.propagation = Propagation::Random;
    else if (p == "S") term.propagation = Propagation::Systematic;
    else if (p == "G") term.propagation = Propagation::Global;
    else if (p == "W") term.propagation = Propagation::WellByWell;
    else throw std::runtime_error(where + "propagation '" + p + "': R, S, G or W");
    if (!known_weight_function(term.weight_function))
      throw std::runtime_error(where + "unknown weighting function '" + term.weight_function + "'");
    if (term.weight_function == "XCL") term.weight_function = term.code == "XCLH" ? "XCLH" : "XCLA";
    try {
      term.magnitude = to_model_unit(term.weight_function, term.magnitude, term.unit);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(where + "term " + term.code + ": " + e.what());
    }
    term.unit = model_unit(term.weight_function);
    t.terms.push_back(term);
  }
  if (t.terms.empty()) throw std::runtime_error(source + ": no terms");
  return t;
}

}  // namespace plumb::survey::iscwsa
