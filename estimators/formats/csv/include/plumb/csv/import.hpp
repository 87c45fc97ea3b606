// Reading other loggers' sensor CSV files as they are: which of their columns holds which plumb
// quantity, in which units, and how their sensor axes sit in the tool frame of docs/conventions.md.
// The command-line forms (`--column`, `--units`, `--axes`) are parsed here so that every tool
// accepts the same text and refuses it with the same line.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/core/sample.hpp"

namespace plumb::csv {

// One group's unit: its name as given and the factor from the file's numbers to plumb's unit.
struct Unit {
  std::string name;
  double scale = 1;
};

struct Import {
  // plumb column name (t, seq, fx..fz, bx..bz, wx..wz, temp_c, depth_m) -> the file's header text.
  // An unmapped plumb column is looked up under its own name.
  std::map<std::string, std::string> columns;
  Unit accel{"m/s2", 1.0};  // to m/s^2
  Unit gyro{"rad/s", 1.0};  // to rad/s
  Unit mag{"uT", 1.0};      // to microtesla
  Unit time{"s", 1.0};      // to seconds
  Unit depth{"m", 1.0};     // to metres
  // tool = axes * sensor, for f, b and w alike: row i is tool axis i in sensor coordinates.
  // A proper rotation (orthonormal, det +1): the tool frame is right-handed, and so must the
  // sensor frame be, or the gyros would turn the wrong way.
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  std::string axes_text = "x,y,z";

  // The plumb columns a mapping may name, in file order.
  static const std::vector<std::string>& plumb_columns();
};

// `NAME=HEADER TEXT`, e.g. `wx=Gyroscope X (deg/s)`; surrounding double quotes on the header text
// are dropped. Throws std::invalid_argument naming --column for an unknown plumb column, an empty
// header text, or a header text already given to another plumb column.
void add_column(Import& import, const std::string& spec);
// `accel=g,gyro=deg/s,mag=gauss,time=ms,depth=ft` (any subset). Throws std::invalid_argument naming
// --units and the accepted values for an unknown group or unit.
void add_units(Import& import, const std::string& spec);
// `x,-y,-z` (tool x = sensor x, tool y = -sensor y, tool z = -sensor z) or nine numbers
// `r11 r12 r13 r21 ... r33` (spaces or commas) of the matrix `axes` above. Throws
// std::invalid_argument naming --axes for anything else, a reflection or a non-orthonormal matrix.
void set_axes(Import& import, const std::string& spec);
// All three at once, as the tools get them from the command line (empty: the default).
Import make_import(const std::vector<std::string>& columns, const std::vector<std::string>& units,
                   const std::string& axes);
// True when the import changes nothing: no mapping, plumb's units, identity axes.
bool is_default(const Import& import);
// One line for logs: "columns wx='Gyroscope X (deg/s)', ...; units accel=g, ...; axes x,-y,-z".
std::string describe(const Import& import);

// Sensor axes to tool axes. Zero entries are skipped, so a NaN on one sensor axis stays on the
// tool axis it maps to and a signed permutation is exact.
Eigen::Vector3d to_tool(const Import& import, const Eigen::Vector3d& sensor);

// Up to `n` of `names` nearest to `wanted` (edit distance, ignoring case), nearest first.
std::vector<std::string> closest_names(const std::string& wanted, const std::vector<std::string>& names,
                                       std::size_t n = 3);

// Plausibility of the units, on samples already read (so in plumb's units) from the start of a
// file, a few seconds are enough. Over the first second the median |f| should be near gravity and
// the median |b| near the Earth's field; over all given samples the gyros should not turn faster
// than a drilling tool can (50 rad/s). Each finding is one line that says what the numbers look
// like and which --units to give; empty when everything is plausible or there is too little data.
std::vector<std::string> check_units(const std::vector<Sample>& first_samples, const Import& declared = {});

}  // namespace plumb::csv
