#include "plumb/calibration/station_list.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <map>
#include <ostream>
#include <sstream>

#include "plumb/core/number.hpp"
#include "plumb/core/trim.hpp"

namespace plumb::calibration {

namespace {

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, sep)) out.push_back(trim(cell));
  if (!line.empty() && line.back() == sep) out.emplace_back();
  return out;
}

double number(const std::string& text, const std::string& where) {
  const auto x = parse_number(text);
  if (!x) throw CalibrationError(where + "bad number '" + text + "'");
  return *x;
}

void write_number(std::ostream& out, double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.write(buf, r.ptr - buf);
}

}  // namespace

std::vector<Station> parse_station_list(std::istream& in, const std::string& source) {
  std::vector<Station> out;
  std::map<std::string, int> col;
  std::map<std::string, int> names;
  std::string line;
  int line_no = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string content = trim(line);
    if (content.empty() || content[0] == '#') continue;
    const auto cells = split(content, ',');
    const std::string where = source + ":" + std::to_string(line_no) + ": ";
    if (!header) {
      for (std::size_t i = 0; i < cells.size(); ++i) col[cells[i]] = static_cast<int>(i);
      for (const char* need : {"name", "start_s", "end_s", "orientation"})
        if (!col.count(need))
          throw CalibrationError(where + "header lacks column '" + need +
                                 "' (needs name,start_s,end_s,orientation; optional run,ref_temp_c)");
      header = true;
      continue;
    }
    const auto cell = [&](const char* name) -> std::string {
      const auto it = col.find(name);
      if (it == col.end()) return {};
      if (it->second >= static_cast<int>(cells.size())) {
        if (std::string(name) == "run" || std::string(name) == "ref_temp_c") return {};
        throw CalibrationError(where + "missing column '" + name + "'");
      }
      return cells[static_cast<std::size_t>(it->second)];
    };
    Station s;
    s.name = cell("name");
    if (s.name.empty()) throw CalibrationError(where + "empty station name");
    if (const auto [it, fresh] = names.emplace(s.name, line_no); !fresh)
      throw CalibrationError(where + "station '" + s.name + "' already given on line " + std::to_string(it->second));
    s.start_s = number(cell("start_s"), where + "column 'start_s': ");
    s.end_s = number(cell("end_s"), where + "column 'end_s': ");
    if (!(s.end_s > s.start_s)) throw CalibrationError(where + "station '" + s.name + "': end_s is not after start_s");
    try {
      s.orientation = parse_orientation(cell("orientation"));
    } catch (const CalibrationError& e) {
      throw CalibrationError(where + "column 'orientation': " + e.what());
    }
    s.run = cell("run");
    const std::string refs = cell("ref_temp_c");
    if (!refs.empty())
      for (const auto& r : split(refs, ';')) s.reference_temps_c.push_back(number(r, where + "column 'ref_temp_c': "));
    out.push_back(s);
  }
  if (!header) throw CalibrationError(source + ": no header line (name,start_s,end_s,orientation)");
  if (out.empty()) throw CalibrationError(source + ": no stations");
  return out;
}

std::vector<Station> read_station_list(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CalibrationError(path + ": cannot open station list");
  return parse_station_list(in, path);
}

void write_station_list(std::ostream& out, const std::vector<Station>& stations) {
  out << "# plumb station list (docs/calibration.md)\nname,start_s,end_s,orientation,run,ref_temp_c\n";
  for (const auto& s : stations) {
    out << s.name << ',';
    write_number(out, s.start_s);
    out << ',';
    write_number(out, s.end_s);
    out << ',' << s.orientation.label() << ',' << s.run << ',';
    for (std::size_t i = 0; i < s.reference_temps_c.size(); ++i) {
      if (i) out << ';';
      write_number(out, s.reference_temps_c[i]);
    }
    out << '\n';
  }
}

}  // namespace plumb::calibration
