#include "plumb/components/survey_options.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "plumb/core/number.hpp"
#include "plumb/csv/files.hpp"
#include "plumb/survey/navigator_tool_code.hpp"
#include "plumb/survey/tool_code_file.hpp"

namespace plumb::components {

void add_survey_options(CLI::App& app, SurveyCliOptions& o) {
  app.add_option("--reference", o.reference, "azimuth reference of the survey: magnetic, true (needs --declination) or "
                                             "grid (needs --declination and --convergence)")
      ->check(CLI::IsMember({"magnetic", "true", "grid"}))
      ->capture_default_str();
  app.add_option("--declination", o.declination_deg, "magnetic declination, deg, east positive (true = magnetic + declination)");
  app.add_option("--declination-sd", o.declination_sd_deg, "declination uncertainty, deg (systematic term DEC)")->capture_default_str();
  app.add_option("--convergence", o.convergence_deg, "grid convergence, deg, grid north east of true north positive "
                                                     "(grid = true - convergence)");
  app.add_option("--gravity", o.gravity, "reference local gravity, m/s^2 (QC of |G|)");
  app.add_option("--total-field", o.total_field, "reference total field, uT (QC of |B|)");
  app.add_option("--dip", o.dip, "reference dip, deg, down positive (QC of dip)");
  app.add_option("--latitude", o.latitude_deg, "latitude of the well, deg (the gyro model's gyrocompass terms: "
                                               "GYRO-NS, GYRO-NS-CT, GYRO-MWD)")
      ->check(CLI::Range(-90.0, 90.0));
  app.add_option("--reference-file", o.reference_file, "reference field file: lines `gravity_mps2 V`, `total_b_uT V`, "
                                                       "`dip_deg V`, `declination_deg V` (options given win)");
  app.add_option("--tol-gravity", o.tol_gravity, "QC tolerance on |G|, m/s^2 (default 0.003 g = 0.0294)");
  app.add_option("--tol-field", o.tol_field, "QC tolerance on |B|, uT (default 0.3 = 300 nT)");
  app.add_option("--tol-dip", o.tol_dip, "QC tolerance on dip, deg (default 0.25)");
  app.add_option("--skip-check", o.skip_checks, "QC check not to run: gravity, field or dip (repeatable)")
      ->check(CLI::IsMember({"gravity", "field", "dip"}));
  app.add_option("--section-azimuth", o.section_azimuth_deg,
                 "vertical-section azimuth, deg, in the survey's reference (default: the closure azimuth of the last "
                 "station, the well's direction)");
  app.add_option("--tie-in", o.tie_in, "position of the first station: NORTH,EAST,TVD in m (default 0,0,0)")
      ->delimiter(',')
      ->expected(3);
  app.add_option("--depth-sd", o.depth_sd_m, "standard deviation of one depth report, m: each station's depth sigma "
                                             "and how far a standing depth may wander (default: what the depth input "
                                             "reports, or measured from the reports' second differences)");
  app.add_option("--depth-scale-sd", o.depth_scale_sd, "depth scale factor uncertainty, relative (systematic term DSF)")
      ->capture_default_str();
  app.add_option("--axial-bias-sd", o.axial_bias_sd_uT, "axial magnetometer bias / drill-string interference "
                                                        "uncertainty, uT (systematic term AMIL)")
      ->capture_default_str();
  app.add_option("--axial-accel-bias-sd", o.axial_accel_bias_sd, "axial accelerometer bias uncertainty, m/s^2 "
                                                                   "(systematic term ABZ)")
      ->capture_default_str();
  app.add_option("--error-model", o.error_model,
                 "position uncertainty: the ISCWSA MWD model with a built-in tool code (MWD = MWD:rev5.1, the OWSG "
                 "revision 5.1 values; MWD:rev5 the ISCWSA revision 5 workbooks' (DEC-OH 0.20 deg); MWD:rev4; "
                 "MWD+IFR1), the ISCWSA gyro model (GYRO-NS, GYRO-NS-CT, GYRO-MWD: OWSG revision 5.1; GYRO:tactical, "
                 "GYRO:mems: plumb's strapdown grades, continuous from a known azimuth), a tool code file "
                 "(code,weight_function,magnitude,unit,propagation), plumb (plumb's own "
                 "terms, --axial-bias-sd and the like), or auto (MWD for a magnetic survey; for the strapdown "
                 "navigator's, the gyro model of the navigator's own figures and alignment, GYRO:navigator, from its "
                 "parameters: plumb survey's --param, plumb-survey asks its estimator host; plumb's own terms when "
                 "they are not known, said)")
      ->capture_default_str();
  app.add_option("--error-model-from", o.error_model_from,
                 "MD:MODEL, a survey program: from this measured depth (m) on, the stations are priced by MODEL (a "
                 "built-in tool code or a tool code file), a leg whose systematic errors are its own draw (repeatable, "
                 "depths increasing; e.g. --error-model GYRO-NS --error-model-from 1200:MWD)");
  app.add_option("--still-tolerance", o.still_tolerance_m, "depth change within a window that still counts as a stop, "
                                                          "m, at least (6.5 depth sigmas when the depth is noisier)")
      ->capture_default_str();
  app.add_option("--stop-station", o.stop_station, "a station from every valid window of a stop (whole) or from its "
                                                   "first valid window (first)")
      ->check(CLI::IsMember({"whole", "first"}))
      ->capture_default_str();
  app.add_option("--min-still", o.min_still_s, "the depth must have stood this long before a window's end, s")
      ->capture_default_str();
  app.add_option("--new-station", o.new_station_m, "a stop closer than this to the last station is the same station, m")
      ->capture_default_str();
  app.add_option("--pipe-length", o.pipe_length_m, "no depth input: pipe tally, one joint of this length per stop, m");
  app.add_option("--tally", o.tally_file, "no depth input: pipe tally CSV, one row per stop: joint_m (the joint run in "
                                         "after that stop), optional correction_m (added to that stop's depth)")
      ->excludes("--pipe-length");
  app.add_option("--start-md", o.start_md_m, "pipe tally: measured depth of the first stop, m")->capture_default_str();
}

namespace {

// A built-in tool code or a tool code file, named by `option` (whose own names are `also`).
std::optional<survey::iscwsa::ToolCode> named_tool_code(const std::string& name, const char* option = "--error-model",
                                                        const char* also = "auto, plumb, ") {
  const auto builtin = survey::iscwsa::builtin_tool_codes();
  if (std::find(builtin.begin(), builtin.end(), name) != builtin.end()) return survey::iscwsa::builtin_tool_code(name);
  std::ifstream in(name);
  if (!in) {
    std::string names;
    for (const auto& n : builtin) names += (names.empty() ? "" : ", ") + n;
    throw std::invalid_argument(std::string(option) + " '" + name + "': no such tool code file (built in: " + also +
                                names + ")");
  }
  return survey::iscwsa::read_tool_code(in, name);
}

}  // namespace

survey::SurveyOptions make_survey_options(const SurveyCliOptions& o, const std::string& estimator,
                                          const survey::iscwsa::NavigatorParameters* navigator) {
  survey::SurveyOptions s;
  s.reference = *survey::parse_azimuth_reference(o.reference);
  if (!o.reference_file.empty()) {
    std::ifstream in(o.reference_file);
    if (!in) throw std::runtime_error("cannot open reference file '" + o.reference_file + "'");
    s.field = survey::read_reference_file(in, o.reference_file);
  }
  if (o.gravity) s.field.gravity_mps2 = *o.gravity;
  if (o.total_field) s.field.total_b_uT = *o.total_field;
  if (o.dip) s.field.dip_deg = *o.dip;
  if (o.latitude_deg) s.latitude_deg = *o.latitude_deg;
  if (o.declination_deg) s.field.declination_deg = *o.declination_deg;
  if (s.field.declination_deg) {
    s.north.declination_deg = *s.field.declination_deg;
    s.north.declination_known = true;
  }
  if (o.convergence_deg) {
    s.north.convergence_deg = *o.convergence_deg;
    s.north.convergence_known = true;
  }
  s.north.declination_sd_deg = o.declination_sd_deg;
  // The error model: the navigator's own gyro model for its stations under auto (from its
  // parameters; without them plumb's own terms, the caller saying why), ISCWSA's MWD model for
  // every other estimator's.
  const bool navigator_stations = estimator == kNavigatorPlugin;
  if (o.error_model == "auto" && navigator_stations) {
    if (navigator) {
      const survey::iscwsa::NavigatorModel m =
          survey::iscwsa::navigator_tool_code(*navigator, s.field.total_b_uT.value_or(50), s.field.dip_deg.value_or(60));
      s.tool_code = m.tool;
      if (!o.latitude_deg) s.latitude_deg = m.latitude_deg;  // the latitude the navigator gyrocompassed at
    }
  } else if (o.error_model == "auto") {
    s.tool_code = survey::iscwsa::builtin_tool_code("MWD");
  } else if (o.error_model != "plumb") {
    s.tool_code = named_tool_code(o.error_model);
  }
  // A navigator's sigma holds its drift since alignment: against a gyro model it counts only by
  // what it exceeds the model's (survey::SurveyOptions::station_sigma_beyond_model).
  s.station_sigma_beyond_model = navigator_stations && s.tool_code && survey::iscwsa::has_gyro_terms(*s.tool_code);
  for (const std::string& leg : o.error_model_from) {
    const auto colon = leg.find(':');
    const auto md = colon == std::string::npos ? std::nullopt : parse_number(leg.substr(0, colon));
    if (!md || colon + 1 >= leg.size())
      throw std::invalid_argument("--error-model-from '" + leg + "': expected MD:MODEL, a measured depth in m and a "
                                  "tool code (e.g. 1200:MWD)");
    if (!s.tool_code)
      throw std::invalid_argument("--error-model-from needs an ISCWSA error model above its depth: --error-model " +
                                  o.error_model + " prices the stations with plumb's own terms" +
                                  (o.error_model == "auto" ? " here (name one: MWD, GYRO-NS, a tool code file)" : ""));
    if (!s.later_legs.empty() && !(*md > s.later_legs.back().from_md_m))
      throw std::invalid_argument("--error-model-from '" + leg + "': the legs' depths must increase");
    s.later_legs.push_back({*md, *named_tool_code(leg.substr(colon + 1), "--error-model-from", "")});
  }
  if (s.reference != survey::AzimuthReference::Magnetic && !s.north.declination_known)
    throw std::invalid_argument("--reference " + o.reference + " needs --declination (or declination_deg in --reference-file)");
  if (s.reference == survey::AzimuthReference::Grid && !s.north.convergence_known)
    throw std::invalid_argument("--reference grid needs --convergence");
  for (const auto& c : o.skip_checks) {
    if (c == "gravity") s.checks.gravity = false;
    if (c == "field") s.checks.total_b = false;
    if (c == "dip") s.checks.dip = false;
  }
  // A check without its reference value would fail every station: say so now, once.
  const auto need = [&](bool check, const auto& value, const char* option, const char* name) {
    if (check && !value)
      throw std::invalid_argument(std::string("missing reference ") + name + ": give " + option +
                                  " or --reference-file, or --skip-check to survey without that QC");
  };
  need(s.checks.gravity, s.field.gravity_mps2, "--gravity", "gravity");
  need(s.checks.total_b, s.field.total_b_uT, "--total-field", "total field");
  need(s.checks.dip, s.field.dip_deg, "--dip", "dip");
  if (o.tol_gravity) s.tolerances.gravity_mps2 = *o.tol_gravity;
  if (o.tol_field) s.tolerances.total_b_uT = *o.tol_field;
  if (o.tol_dip) s.tolerances.dip_deg = *o.tol_dip;
  s.section_azimuth_deg = o.section_azimuth_deg;
  if (o.tie_in.size() == 3) s.tie_in = Eigen::Vector3d(o.tie_in[0], o.tie_in[1], o.tie_in[2]);
  if (!(o.depth_scale_sd >= 0) || !(o.axial_bias_sd_uT >= 0) || !(o.declination_sd_deg >= 0) ||
      !(o.axial_accel_bias_sd >= 0))
    throw std::invalid_argument("--declination-sd, --depth-scale-sd, --axial-bias-sd and --axial-accel-bias-sd must be >= 0");
  s.errors.depth_scale_sd = o.depth_scale_sd;
  s.errors.axial_bias_sd_uT = o.axial_bias_sd_uT;
  s.errors.axial_accel_bias_sd_mps2 = o.axial_accel_bias_sd;
  return s;
}

namespace {

survey::PipeTally read_tally_file(const std::string& path, double start_md_m, double sd_m) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open tally file '" + path + "'");
  survey::PipeTally tally{start_md_m, {}, {}, sd_m};
  std::string line;
  std::size_t n = 0;
  int joint = -1, correction = -1;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const auto fields = csv::split_line(line);
    const std::string where = path + ":" + std::to_string(n) + ": ";
    if (joint < 0) {
      for (std::size_t i = 0; i < fields.size(); ++i) {
        if (fields[i] == "joint_m") joint = static_cast<int>(i);
        if (fields[i] == "correction_m") correction = static_cast<int>(i);
      }
      if (joint < 0) throw std::runtime_error(where + "no column 'joint_m' in the header");
      continue;
    }
    const auto value = [&](int column, const char* name) {
      const std::string text = static_cast<std::size_t>(column) < fields.size() ? fields[static_cast<std::size_t>(column)] : "";
      const auto v = parse_number(text);
      if (!v) throw std::runtime_error(where + "column '" + name + "': bad number '" + text + "'");
      return *v;
    };
    const double j = value(joint, "joint_m");
    if (!(j > 0)) throw std::runtime_error(where + "joint_m must be > 0");
    tally.joint_lengths_m.push_back(j);
    tally.corrections_m.push_back(correction >= 0 ? value(correction, "correction_m") : 0.0);
  }
  if (tally.joint_lengths_m.empty()) throw std::runtime_error(path + ": no tally rows");
  return tally;
}

}  // namespace

survey::DetectorOptions make_detector_options(const SurveyCliOptions& o) {
  survey::DetectorOptions d;
  d.still_tolerance_m = o.still_tolerance_m;
  d.new_station_m = o.new_station_m;
  d.min_still_s = o.min_still_s;
  d.depth_sd_m = o.depth_sd_m;
  d.whole_stop = o.stop_station != "first";
  if (!(d.min_still_s >= 0)) throw std::invalid_argument("--min-still must be >= 0");
  if (!(d.still_tolerance_m > 0) || !(d.new_station_m > 0))
    throw std::invalid_argument("--still-tolerance and --new-station must be > 0");
  if (o.pipe_length_m) {
    if (!(*o.pipe_length_m > 0)) throw std::invalid_argument("--pipe-length must be > 0");
    d.tally = survey::PipeTally{o.start_md_m, {*o.pipe_length_m}, {}, std::max(0.0, o.depth_sd_m)};
  }
  if (!o.tally_file.empty()) d.tally = read_tally_file(o.tally_file, o.start_md_m, std::max(0.0, o.depth_sd_m));
  return d;
}

}  // namespace plumb::components
