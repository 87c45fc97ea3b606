#include "plumb/survey/survey_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "plumb/core/number.hpp"
#include "plumb/csv/files.hpp"
#include "plumb/survey/file_precision.hpp"

namespace plumb::survey {
namespace {

// The columns, in order; the inputs a restart reads back are marked in read_survey_file.
const char* const kColumns[] = {
    "station", "t", "tool_id", "source", "md_m", "md_sd_m", "inclination_deg", "inclination_sd_deg", "azimuth_deg",
    "azimuth_sd_deg", "azimuth_reference", "magnetic_azimuth_deg", "azimuth_valid", "north_m", "east_m", "tvd_m",
    "dogleg_deg", "dls_deg_per_30m", "dls_deg_per_100ft", "vertical_section_m", "closure_distance_m",
    "closure_azimuth_deg", "north_sd_m", "east_sd_m", "tvd_sd_m", "ellipse_major_sd_m", "ellipse_minor_sd_m",
    "ellipse_major_azimuth_deg", "cov_nn", "cov_ne", "cov_nd", "cov_ee", "cov_ed", "cov_dd", "total_g_mps2",
    "total_b_uT", "dip_deg", "g_residual_mps2", "b_residual_uT", "dip_residual_deg", "gravity_toolface_deg",
    "toolface_sd_deg", "windows", "inclination_random_sd_deg", "inclination_total_sd_deg", "azimuth_random_sd_deg",
    "azimuth_total_sd_deg", "random_north_sd_m", "random_east_sd_m", "random_tvd_sd_m", "random_ellipse_major_sd_m",
    "random_ellipse_minor_sd_m", "reference_g_mps2", "reference_b_uT", "reference_dip_deg", "error_model", "qc",
    "qc_reason"};
constexpr std::size_t kColumnCount = sizeof(kColumns) / sizeof(kColumns[0]);

std::string header_line() {
  std::string h;
  for (std::size_t i = 0; i < kColumnCount; ++i) h += (i ? "," : "") + std::string(kColumns[i]);
  return h;
}

// Free text in a CSV field: plumb's files never quote, so commas and line breaks become blanks.
std::string field_text(std::string s) {
  for (char& c : s)
    if (c == ',' || c == '\n' || c == '\r') c = ' ';
  return s;
}

// Each column at the precision fit for it (plumb/survey/file_precision.hpp): `fixed` for depths,
// positions, angles, times and fields, `sigma` for standard deviations. A station's inputs enter
// the survey already rounded so, and read back as the same doubles.
std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return "nan";
  double rounded = precision::round_decimals(v, decimals);
  if (rounded == 0) rounded = 0;  // no "-0.000"
  char buffer[64];
  const int n = std::snprintf(buffer, sizeof buffer, "%.*f", decimals, rounded);
  return std::string(buffer, n > 0 && n < static_cast<int>(sizeof buffer) ? static_cast<std::size_t>(n) : 0);
}
std::string metres(double v) { return fixed(v, precision::kMetreDecimals); }
std::string degrees(double v) { return fixed(v, precision::kDegreeDecimals); }
std::string sigma(double v) {
  if (!std::isfinite(v)) return "nan";
  char buffer[32];
  const int n = std::snprintf(buffer, sizeof buffer, "%.*g", precision::kSigmaDigits, precision::round_sigma(v));
  return std::string(buffer, n > 0 && n < static_cast<int>(sizeof buffer) ? static_cast<std::size_t>(n) : 0);
}

// The shortest text that reads back as the same double: the covariances (a clearance scan reads
// them back) and the reference field as given.
std::string num(double v) {
  if (!std::isfinite(v)) return "nan";
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, end) : "nan";
}

std::string optional_num(const std::optional<double>& v) { return v ? num(*v) : "nan"; }

void throw_errno(const std::string& what, const std::string& path) {
  throw std::runtime_error(what + " '" + path + "': " + std::strerror(errno));
}

void write_all(int fd, const std::string& text, const std::string& path) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw_errno("cannot write", path);
    }
    done += static_cast<std::size_t>(n);
  }
}

void sync_folder(const std::string& path) {
  const auto folder = std::filesystem::absolute(path).parent_path();
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

void write_survey_header(std::ostream& out, const SurveyOptions& o, double closure_azimuth_deg) {
  out << kSurveyFormatLine << '\n';
  out << "# azimuth_reference " << to_string(o.reference);
  if (o.north.declination_known) out << " declination_deg " << num(o.north.declination_deg);
  if (o.north.convergence_known) out << " convergence_deg " << num(o.north.convergence_deg);
  if (o.section_azimuth_deg)
    out << " section_azimuth_deg " << num(*o.section_azimuth_deg) << '\n';
  else
    out << " section_azimuth_deg " << degrees(closure_azimuth_deg) << " (closure)\n";
  out << "# reference gravity_mps2 " << (o.field.gravity_mps2 ? num(*o.field.gravity_mps2) : "none") << " total_b_uT "
      << (o.field.total_b_uT ? num(*o.field.total_b_uT) : "none") << " dip_deg "
      << (o.field.dip_deg ? num(*o.field.dip_deg) : "none") << "; tolerances " << num(o.tolerances.gravity_mps2)
      << " m/s^2, " << num(o.tolerances.total_b_uT) << " uT, " << num(o.tolerances.dip_deg) << " deg\n";
  out << header_line() << '\n';
}

std::string survey_row_line(const SurveyRow& r) {
  const Station& s = r.station;
  const auto& p = r.point;
  const auto& u = r.uncertainty;
  const auto& c = u.covariance;
  const auto& q = r.qc;
  std::ostringstream o;
  using precision::kFieldDecimals, precision::kGravityDecimals, precision::kSecondDecimals;
  o << r.index << ',' << fixed(s.t_s, kSecondDecimals) << ',' << field_text(s.tool_id) << ',' << field_text(s.source)
    << ',' << metres(s.md_m) << ',' << sigma(s.md_sd_m) << ',' << degrees(s.inclination_deg) << ','
    << sigma(s.inclination_sd_deg) << ',' << degrees(r.azimuth_deg) << ',' << sigma(s.azimuth_sd_deg) << ','
    << to_string(r.reference) << ',' << degrees(s.magnetic_azimuth_deg) << ',' << (s.azimuth_valid ? 1 : 0) << ','
    << metres(p.north_m) << ',' << metres(p.east_m) << ',' << metres(p.tvd_m) << ',' << degrees(p.dogleg_deg) << ','
    << degrees(p.dls_deg_per_30m) << ',' << degrees(p.dls_deg_per_100ft) << ',' << metres(p.vertical_section_m) << ','
    << metres(p.closure_distance_m) << ',' << degrees(p.closure_azimuth_deg) << ',' << sigma(u.north_sd_m) << ','
    << sigma(u.east_sd_m) << ',' << sigma(u.tvd_sd_m) << ',' << sigma(u.major_sd_m) << ',' << sigma(u.minor_sd_m) << ','
    << degrees(u.major_azimuth_deg) << ',' << num(c(0, 0)) << ',' << num(c(0, 1)) << ',' << num(c(0, 2)) << ','
    << num(c(1, 1)) << ',' << num(c(1, 2)) << ',' << num(c(2, 2)) << ',' << fixed(s.total_g_mps2, kGravityDecimals)
    << ',' << fixed(s.total_b_uT, kFieldDecimals) << ',' << degrees(s.dip_deg) << ','
    << fixed(q.gravity_residual_mps2, kGravityDecimals) << ',' << fixed(q.total_b_residual_uT, kFieldDecimals) << ','
    << degrees(q.dip_residual_deg) << ',' << degrees(s.toolface_deg) << ',' << sigma(s.toolface_sd_deg) << ','
    << s.windows << ',' << sigma(r.inclination_random_sd_deg) << ',' << sigma(r.inclination_total_sd_deg) << ','
    << sigma(r.azimuth_random_sd_deg) << ',' << sigma(r.azimuth_total_sd_deg) << ','
    << sigma(r.random_uncertainty.north_sd_m) << ',' << sigma(r.random_uncertainty.east_sd_m) << ','
    << sigma(r.random_uncertainty.tvd_sd_m) << ',' << sigma(r.random_uncertainty.major_sd_m) << ','
    << sigma(r.random_uncertainty.minor_sd_m) << ',' << optional_num(r.field.gravity_mps2) << ','
    << optional_num(r.field.total_b_uT) << ',' << optional_num(r.field.dip_deg) << ',' << field_text(r.error_model)
    << ',' << (q.pass ? "pass" : "fail") << ','
    << field_text(q.reason.empty() ? r.warning : (r.warning.empty() ? q.reason : q.reason + "; " + r.warning))
    << '\n';
  return o.str();
}

void write_survey_row(std::ostream& out, const SurveyRow& row) { out << survey_row_line(row); }

std::string survey_text(const Survey& survey) {
  std::ostringstream out;
  write_survey_header(out, survey.options(), survey.section_azimuth_deg());
  std::string text = out.str();
  for (const auto& row : survey.rows()) text += survey_row_line(row);
  return text;
}

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw_errno("cannot write", tmp);
  try {
    write_all(fd, text, tmp);
    if (::fsync(fd) != 0) throw_errno("cannot sync", tmp);
  } catch (...) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  ::close(fd);
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    ::unlink(tmp.c_str());
    throw_errno("cannot rename to", path);
  }
  sync_folder(path);
}

LoadedSurvey read_survey_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open survey file '" + path + "'");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  LoadedSurvey out;
  std::size_t pos = 0, line_no = 0;
  bool format_seen = false;
  std::map<std::string, std::size_t> col;
  while (pos < text.size()) {
    const auto end = text.find('\n', pos);
    ++line_no;
    const std::string where = path + ":" + std::to_string(line_no) + ": ";
    if (end == std::string::npos) {
      out.problem = where + "last line truncated (no end of line: the writer stopped in the middle of it)";
      return out;
    }
    std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!format_seen) {
      if (line != kSurveyFormatLine && line != kSurveyFormatLineV1)
        throw std::runtime_error(where + "not a plumb survey file (first line must be '" + kSurveyFormatLine + "')");
      format_seen = true;
      out.valid_lines = line_no;
      continue;
    }
    if (line.empty() || line[0] == '#') {
      out.valid_lines = line_no;
      continue;
    }
    const auto fields = csv::split_line(line);
    if (col.empty()) {
      for (std::size_t i = 0; i < fields.size(); ++i) col[fields[i]] = i;
      for (const char* needed : {"station", "t", "tool_id", "source", "md_m", "md_sd_m", "inclination_deg",
                                 "inclination_sd_deg", "magnetic_azimuth_deg", "azimuth_sd_deg", "azimuth_valid",
                                 "total_g_mps2", "total_b_uT", "dip_deg", "qc"})
        if (!col.count(needed))
          throw std::runtime_error(where + "unexpected column header (no column '" + needed + "': not a survey file)");
      out.valid_lines = line_no;
      continue;
    }
    try {
      if (fields.size() != col.size())
        throw std::runtime_error(std::to_string(fields.size()) + " fields, expected " + std::to_string(col.size()));
      const auto number = [&](const char* name, bool allow_nan = false) {
        const auto v = parse_number(fields[col.at(name)], allow_nan);
        if (!v || (!allow_nan && !std::isfinite(*v)))
          throw std::runtime_error("column '" + std::string(name) + "': bad number '" + fields[col.at(name)] + "'");
        return *v;
      };
      const double index = number("station");
      if (index != static_cast<double>(out.stations.size()))
        throw std::runtime_error("station number " + fields[col.at("station")] + ", expected " +
                                 std::to_string(out.stations.size()));
      Station s;
      s.t_s = number("t");
      s.tool_id = fields[col.at("tool_id")];
      s.source = fields[col.at("source")];
      s.md_m = number("md_m");
      s.md_sd_m = number("md_sd_m");
      s.inclination_deg = number("inclination_deg");
      s.inclination_sd_deg = number("inclination_sd_deg");
      s.magnetic_azimuth_deg = number("magnetic_azimuth_deg");
      s.azimuth_sd_deg = number("azimuth_sd_deg");
      s.azimuth_valid = number("azimuth_valid") != 0;
      s.total_g_mps2 = number("total_g_mps2", true);
      s.total_b_uT = number("total_b_uT", true);
      s.dip_deg = number("dip_deg", true);
      if (col.count("gravity_toolface_deg")) {
        s.toolface_deg = number("gravity_toolface_deg", true);
        s.toolface_sd_deg = number("toolface_sd_deg", true);
        s.windows = static_cast<std::uint32_t>(number("windows"));
      }
      const std::string qc = fields[col.at("qc")];
      if (qc != "pass" && qc != "fail") throw std::runtime_error("column 'qc': '" + qc + "' is neither pass nor fail");
      out.stations.push_back(s);
      out.valid_lines = line_no;
    } catch (const std::exception& e) {
      out.problem = where + "damaged row (" + e.what() + ")";
      return out;
    }
  }
  if (!format_seen) throw std::runtime_error(path + ": empty, not a plumb survey file");
  if (col.empty()) out.problem = path + ": no column header (the file was cut before it)";
  return out;
}

SurveyAppender::SurveyAppender(const std::string& path, const SurveyOptions& options) : path_(path) {
  std::error_code ec;
  const bool fresh = !std::filesystem::exists(path, ec) || std::filesystem::file_size(path, ec) == 0;
  if (fresh) {
    std::ostringstream header;
    write_survey_header(header, options);
    write_file_atomically(path, header.str());
  }
  fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) throw_errno("cannot append to survey file", path);
}

SurveyAppender::~SurveyAppender() {
  if (fd_ >= 0) ::close(fd_);
}

void SurveyAppender::append(const SurveyRow& row) {
  // One write() of the whole row (O_APPEND), then fsync: after a crash the row is there whole, or
  // it is a truncated last line that read_survey_file reports and drops.
  write_all(fd_, survey_row_line(row), path_);
  if (::fsync(fd_) != 0) throw_errno("cannot sync survey file", path_);
}

void SurveyAppender::append_comment(const std::string& text) {
  std::string line = "# " + text;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  write_all(fd_, line + "\n", path_);
  if (::fsync(fd_) != 0) throw_errno("cannot sync survey file", path_);
}

}  // namespace plumb::survey
