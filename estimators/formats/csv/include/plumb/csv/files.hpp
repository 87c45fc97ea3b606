// The CSV files of docs/conventions.md: sensor CSV (read and write), attitude CSV and truth CSV
// (write, and read for the tools that compare). UTF-8, one header line, '#' comment lines, commas.
#pragma once

#include <cstdint>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "plumb/csv/import.hpp"
#include "plumb/core/estimate.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::csv {

// A problem in a CSV file, naming where: "sensor.csv:12: column 'fy': bad number 'abc'".
struct Error : std::runtime_error {
  Error(const std::string& source, std::size_t line, const std::string& column, const std::string& what);
  std::string source;
  std::size_t line;    // 1-based
  std::string column;  // empty when the problem is not one column's
};

// Reads a sensor CSV row by row. The header must name t, fx, fy, fz; bx, by, bz and wx, wy, wz
// (each all three or none), temp_c and depth_m are optional; other columns are ignored. Without
// magnetometer columns samples carry flags::kNoMagnetometer and b = 0. Sequence numbers come
// from an optional `seq` column, else they count rows from 0. Fields may be double-quoted (RFC 4180,
// within one line), as other loggers write them.
class SensorReader {
 public:
  // Throws Error when the header lacks a required column. With an `import` (csv_import.hpp), its
  // mapped header texts are looked up instead of plumb's names (a missing one is an Error naming
  // the plumb column, the text and the nearest header names), and every row is converted to
  // plumb's units and tool axes.
  SensorReader(std::istream& in, std::string source_name, const Import& import = {});
  // Next data row into `out`; false at end of file. A bad row throws Error and is skipped, so the
  // caller may count it and call next() again. Non-finite values are kept and flagged kNotFinite.
  bool next(Sample& out);
  bool has_gyro() const { return col_w_[0] >= 0; }
  bool has_magnetometer() const { return col_b_[0] >= 0; }
  bool has_temperature() const { return col_temp_ >= 0; }
  bool has_depth() const { return col_depth_ >= 0; }
  std::size_t line() const { return line_; }

 private:
  std::istream& in_;
  std::string source_;
  std::size_t line_ = 0;
  std::size_t columns_ = 0;
  std::uint64_t rows_ = 0;
  int col_t_ = -1, col_seq_ = -1, col_temp_ = -1, col_depth_ = -1;
  int col_f_[3] = {-1, -1, -1}, col_b_[3] = {-1, -1, -1}, col_w_[3] = {-1, -1, -1};
  std::vector<std::string> names_;
  Import import_;
  bool convert_ = false;  // import_ changes units or axes
};

// Whole file; throws Error on the first bad row.
std::vector<Sample> read_sensor_file(const std::string& path, const Import& import = {});

void write_sensor_header(std::ostream& out, bool with_gyro, bool with_temperature, bool with_depth = false);
void write_sensor_row(std::ostream& out, const Sample& s, bool with_gyro, bool with_temperature, bool with_depth = false);

// Attitude CSV: t,inclination_deg,azimuth_deg,toolface_deg,rpm,valid, then the extra columns
// magnetic_toolface_deg, inclination_sd_deg, azimuth_sd_deg, toolface_sd_deg, dip_deg, total_g,
// total_b, samples_used, azimuth_valid, toolface_valid, estimator, reason. t is the window end.
// A navigator's file (with_navigation) has north_m,east_m,down_m,vn_mps,ve_mps,vd_mps right after
// `valid` (docs/conventions.md), and their standard deviations, still and zupt_count, azimuth_reference
// at the end.
void write_attitude_header(std::ostream& out, bool with_navigation = false);
void write_attitude_row(std::ostream& out, const Estimate& e, bool with_navigation = false);

// Truth CSV; with_position adds north_m,east_m,down_m,vn_mps,ve_mps,vd_mps,depth_m (drilling runs).
void write_truth_header(std::ostream& out, bool with_position = false);
void write_truth_row(std::ostream& out, const TruthSample& s, bool with_position = false);
std::vector<TruthSample> read_truth_file(const std::string& path);

// Splits one CSV line on commas, trimming spaces and CR. plumb's files never quote; a field that
// starts with '"' is read as RFC 4180 quoted text ("" is one quote) for other loggers' files.
std::vector<std::string> split_line(const std::string& line);

}  // namespace plumb::csv
