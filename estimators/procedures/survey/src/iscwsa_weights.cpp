#include "iscwsa_weights.hpp"

#include <cmath>
#include <map>

namespace plumb::survey::iscwsa::detail {
namespace {

using V = Eigen::Vector3d;
const double kRoot2 = std::sqrt(2.0);

double horizontal(const WeightContext& c) { return c.total_b_nT * std::cos(c.dip); }

// Toolface-independent accelerometer and magnetometer terms (A = magnetic azimuth).
V abxy_ti1(const WeightContext& c) {
  return {0, -std::cos(c.inc) / c.gravity, std::tan(c.dip) * std::cos(c.inc) * std::sin(c.azm) / c.gravity};
}
V abxy_ti2(const WeightContext& c) {
  return {0, 0, (1.0 / std::tan(c.inc) - std::tan(c.dip) * std::cos(c.azm)) / c.gravity};
}
V abz(const WeightContext& c) {
  return {0, -std::sin(c.inc) / c.gravity, std::tan(c.dip) * std::sin(c.inc) * std::sin(c.azm) / c.gravity};
}
V asxy_ti1(const WeightContext& c) {
  const double si = std::sin(c.inc), ci = std::cos(c.inc);
  return {0, si * ci / kRoot2, -std::tan(c.dip) * si * ci * std::sin(c.azm) / kRoot2};
}
V asxy_ti2(const WeightContext& c) {
  const double si = std::sin(c.inc), ci = std::cos(c.inc);
  return {0, si * ci / 2, -std::tan(c.dip) * si * ci * std::sin(c.azm) / 2};
}
V asxy_ti3(const WeightContext& c) {
  return {0, 0, (std::tan(c.dip) * std::sin(c.inc) * std::cos(c.azm) - std::cos(c.inc)) / 2};
}
V asz(const WeightContext& c) {
  const double si = std::sin(c.inc), ci = std::cos(c.inc);
  return {0, -si * ci, std::tan(c.dip) * si * ci * std::sin(c.azm)};
}
V mbxy_ti1(const WeightContext& c) { return {0, 0, -std::cos(c.inc) * std::sin(c.azm) / horizontal(c)}; }
V mbxy_ti2(const WeightContext& c) { return {0, 0, std::cos(c.azm) / horizontal(c)}; }
V mbz(const WeightContext& c) { return {0, 0, -std::sin(c.inc) * std::sin(c.azm) / horizontal(c)}; }
V msxy_ti1(const WeightContext& c) {
  const double si = std::sin(c.inc), ci = std::cos(c.inc);
  return {0, 0, si * std::sin(c.azm) * (std::tan(c.dip) * ci + si * std::cos(c.azm)) / kRoot2};
}
V msxy_ti2(const WeightContext& c) {
  const double si = std::sin(c.inc), ci = std::cos(c.inc), ca = std::cos(c.azm);
  return {0, 0, std::sin(c.azm) * (std::tan(c.dip) * si * ci - ci * ci * ca - ca) / 2};
}
V msxy_ti3(const WeightContext& c) {
  const double si = std::sin(c.inc), ci = std::cos(c.inc), ca = std::cos(c.azm), sa = std::sin(c.azm);
  return {0, 0, (ci * ca * ca - ci * sa * sa - std::tan(c.dip) * si * ca) / 2};
}
V msz(const WeightContext& c) {
  const double si = std::sin(c.inc);
  return {0, 0, -(si * std::cos(c.azm) + std::tan(c.dip) * std::cos(c.inc)) * si * std::sin(c.azm)};
}
// A gyro tool's accelerometers (the ISCWSA gyro model, SPE 90408 Tables 1 and 2). A triad:
// misalignment, scale factor (the model's 1.3 sin I cos I), the x-y and the z biases (the closed
// form's dI = cosI b / g and -sinI b / g). X-y accelerometers only, the inclination from the
// radial gravity alone: bias 1 / (g cosI), scale factor tanI, misalignment, and a bias proportional
// to gravity (tanI / g).
V axyz_mis(const WeightContext&) { return {0, 1, 0}; }
V axyz_sf(const WeightContext& c) { return {0, 1.3 * std::sin(c.inc) * std::cos(c.inc), 0}; }
V axyz_xyb(const WeightContext& c) { return {0, std::cos(c.inc) / c.gravity, 0}; }
V axyz_zb(const WeightContext& c) { return {0, std::sin(c.inc) / c.gravity, 0}; }
// Canted x-y accelerometers see the inclination less their cant, the tool turned over beyond
// horizontal (SPE 90408 Table 2, its note 5: k = 1 to 90 deg, -1 beyond).
double axy_inc(const WeightContext& c) { return c.inc - (c.inc <= std::acos(0.0) ? 1 : -1) * c.cant; }
V axy_b(const WeightContext& c) { return {0, 1 / (c.gravity * std::cos(axy_inc(c))), 0}; }
V axy_sf(const WeightContext& c) { return {0, std::tan(axy_inc(c)), 0}; }
V axy_mis(const WeightContext&) { return {0, 1, 0}; }
V axy_gb(const WeightContext& c) { return {0, std::tan(axy_inc(c)) / c.gravity, 0}; }
// Depth.
V dref(const WeightContext&) { return {1, 0, 0}; }
V dsf(const WeightContext& c) { return {c.md, 0, 0}; }
V dst(const WeightContext& c) { return {c.md * c.tvd, 0, 0}; }
// Declination and the axial magnetic interference.
V az(const WeightContext&) { return {0, 0, 1}; }
V dbh(const WeightContext& c) { return {0, 0, 1.0 / horizontal(c)}; }
V amil(const WeightContext& c) { return {0, 0, std::sin(c.inc) * std::sin(c.azm) / horizontal(c)}; }
// Sag and misalignment (A = azimuth of the position frame).
V sag(const WeightContext& c) { return {0, std::sin(c.inc), 0}; }
V sage(const WeightContext& c) { return {0, std::pow(std::sin(c.inc), 0.25), 0}; }
V xym1(const WeightContext& c) { return {0, std::abs(std::sin(c.inc)), 0}; }
V xym2(const WeightContext&) { return {0, 0, -1}; }
V xym3(const WeightContext& c) {
  const double ci = std::abs(std::cos(c.inc));
  return {0, ci * std::cos(c.azi), -ci * std::sin(c.azi) / std::sin(c.inc)};
}
V xym4(const WeightContext& c) {
  const double ci = std::abs(std::cos(c.inc));
  return {0, ci * std::sin(c.azi), ci * std::cos(c.azi) / std::sin(c.inc)};
}

}  // namespace

WeightFunction weight_function(const std::string& name) {
  static const std::map<std::string, WeightFunction> functions = {
      {"DREF", {dref}}, {"DSF", {dsf}}, {"DST", {dst}},
      {"ABXY-TI1", {abxy_ti1}}, {"ABXY-TI2", {abxy_ti2, Vertical::AccelerometerXY}}, {"ABZ", {abz}},
      {"ASXY-TI1", {asxy_ti1}}, {"ASXY-TI2", {asxy_ti2}}, {"ASXY-TI3", {asxy_ti3}}, {"ASZ", {asz}},
      {"MBXY-TI1", {mbxy_ti1}}, {"MBXY-TI2", {mbxy_ti2}}, {"MBZ", {mbz}},
      {"MSXY-TI1", {msxy_ti1}}, {"MSXY-TI2", {msxy_ti2}}, {"MSXY-TI3", {msxy_ti3}}, {"MSZ", {msz}},
      {"AZ", {az}}, {"DBH", {dbh}}, {"AMIL", {amil}},
      {"AXYZ-MIS", {axyz_mis}}, {"AXYZ-SF", {axyz_sf}}, {"AXYZ-XYB", {axyz_xyb}}, {"AXYZ-ZB", {axyz_zb}},
      {"AXY-B", {axy_b}}, {"AXY-SF", {axy_sf}}, {"AXY-MIS", {axy_mis}}, {"AXY-GB", {axy_gb}},
      {"SAG", {sag}}, {"SAGE", {sage}}, {"XYM1", {xym1}}, {"XYM2", {xym2}},
      {"XYM3", {xym3, Vertical::MisalignmentNorth}}, {"XYM4", {xym4, Vertical::MisalignmentEast}},
      // Revision 5's course-length-weighted misalignments (the workbooks call them XYM3L, XYM4L).
      {"XYM3E", {xym3, Vertical::MisalignmentNorth, true}}, {"XYM4E", {xym4, Vertical::MisalignmentEast, true}},
      {"XYM3L", {xym3, Vertical::MisalignmentNorth, true}}, {"XYM4L", {xym4, Vertical::MisalignmentEast, true}},
  };
  const auto it = functions.find(name);
  return it == functions.end() ? WeightFunction{} : it->second;
}

bool is_course_length_term(const std::string& name, const std::string&) {
  return name == "XCL" || name == "XCLA" || name == "XCLH";
}

bool is_azimuth_reference_term(const std::string& name) { return name == "AZ" || name == "DBH"; }

}  // namespace plumb::survey::iscwsa::detail
