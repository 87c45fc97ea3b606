#include "plumb/survey/survey.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "plumb/core/attitude.hpp"
#include "plumb/survey/file_precision.hpp"

namespace plumb::survey {
namespace {

std::string number(double v) {
  std::ostringstream o;
  o.precision(10);
  o << v;
  return o.str();
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

}  // namespace

Survey::Survey(SurveyOptions o) : options_(std::move(o)) {
  // Fails now, not at the first station, when the reference needs a correction that is missing.
  (void)convert_magnetic_azimuth(0, options_.reference, options_.north);
  const auto& t = options_.tolerances;
  require(t.gravity_mps2 > 0 && t.total_b_uT > 0 && t.dip_deg > 0, "QC tolerances must be > 0");
  require(!options_.section_azimuth_deg || std::isfinite(*options_.section_azimuth_deg),
          "the vertical-section azimuth must be finite");
  require(options_.tie_in.allFinite(), "the tie-in position must be finite");
  require(std::isfinite(options_.north.declination_sd_deg) && options_.north.declination_sd_deg >= 0,
          "the declination sigma must be >= 0");
  options_.errors.declination_sd_deg =
      options_.reference == AzimuthReference::Magnetic ? 0.0 : options_.north.declination_sd_deg;
  if (options_.field.total_b_uT) options_.errors.total_b_uT = *options_.field.total_b_uT;
  if (options_.field.dip_deg) options_.errors.dip_deg = *options_.field.dip_deg;
  if (options_.field.gravity_mps2) options_.errors.gravity_mps2 = *options_.field.gravity_mps2;
  require(options_.later_legs.empty() || options_.tool_code,
          "a survey program's later legs need an ISCWSA error model for the stations above them");
  for (std::size_t l = 0; l < options_.later_legs.size(); ++l)
    require(std::isfinite(options_.later_legs[l].from_md_m) &&
                (l == 0 || options_.later_legs[l].from_md_m > options_.later_legs[l - 1].from_md_m),
            "a survey program's legs must start at increasing, finite measured depths");
  if (options_.tool_code) prepare(*options_.tool_code);
  for (auto& leg : options_.later_legs) prepare(leg.tool);
}

std::string error_model_text(const SurveyOptions& options) {
  if (!options.tool_code) return "plumb";
  std::string out = options.tool_code->name;
  for (const auto& leg : options.later_legs) out += "; from MD " + number(leg.from_md_m) + " m " + leg.tool.name;
  return out;
}

void Survey::prepare(iscwsa::ToolCode& tool) const {
  require(!iscwsa::needs_latitude(tool) || std::isfinite(options_.latitude_deg),
          "the error model " + tool.name + " gyrocompasses: it needs the well's latitude (--latitude)");
  if (options_.reference == AzimuthReference::Magnetic) {
    auto& terms = tool.terms;
    terms.erase(std::remove_if(terms.begin(), terms.end(),
                               [](const iscwsa::Term& t) { return t.weight_function == "AZ" || t.weight_function == "DBH"; }),
                terms.end());
  }
}

void Survey::start_leg(iscwsa::ToolCode tool) {
  require(options_.tool_code.has_value(), "a survey leg needs an ISCWSA error model for the stations above it");
  prepare(tool);
  if (rows_.empty()) {
    options_.tool_code = std::move(tool);
    return;
  }
  // Every later station lies deeper than this (duplicates are refused). The program's legs that
  // start deeper stay: they were given for depths not reached yet.
  iscwsa::insert_leg(options_.later_legs, {rows_.back().station.md_m + kDuplicateDepthM, std::move(tool)});
}

const iscwsa::ToolCode* Survey::tool_code_at(double md_m) const {
  for (auto leg = options_.later_legs.rbegin(); leg != options_.later_legs.rend(); ++leg)
    if (md_m >= leg->from_md_m) return &leg->tool;
  return options_.tool_code ? &*options_.tool_code : nullptr;
}

namespace {

// A station's sigma beyond the model's own at that station: the excess variance of each angle
// (0 where the model's is larger; the whole sigma where the model's is not a number).
StationSigma beyond_model(StationSigma s, const Eigen::Vector2d& model_variance_rad2) {
  const auto excess = [](double sd_deg, double model_rad2) {
    const double model_deg2 = model_rad2 / (kDeg * kDeg);
    return std::isfinite(model_deg2) ? std::sqrt(std::max(0.0, sd_deg * sd_deg - model_deg2)) : sd_deg;
  };
  s.inclination_sd_deg = excess(s.inclination_sd_deg, model_variance_rad2(0));
  s.azimuth_sd_deg = excess(s.azimuth_sd_deg, model_variance_rad2(1));
  return s;
}

}  // namespace

void Survey::add_model_uncertainty(SurveyRow& row) {
  const Station& s = row.station;
  std::optional<iscwsa::Result> model;
  if (options_.tool_code) {
    std::vector<iscwsa::Station> stations;
    for (std::size_t k = 0; k < geometry_.size(); ++k) {
      const PathPoint& p = k < rows_.size() ? rows_[k].point : row.point;
      const double magnetic = k < rows_.size() ? rows_[k].station.magnetic_azimuth_deg : s.magnetic_azimuth_deg;
      const double t = k < rows_.size() ? rows_[k].station.t_s : s.t_s;
      stations.push_back({geometry_[k].md_m, geometry_[k].inclination_deg, geometry_[k].azimuth_deg, magnetic,
                          p.tvd_m - options_.tie_in.z(), t});
    }
    iscwsa::Field field;
    field.gravity_mps2 = options_.errors.gravity_mps2;
    field.total_b_nT = options_.errors.total_b_uT * 1000.0;
    field.dip_deg = options_.errors.dip_deg;
    field.latitude_deg = options_.latitude_deg;
    field.true_azimuth_offset_deg = true_azimuth_offset_deg(options_.reference, options_.north);
    field.first_station_surveyed = options_.first_station_surveyed;
    std::vector<iscwsa::Leg> legs{{-std::numeric_limits<double>::infinity(), *options_.tool_code}};
    legs.insert(legs.end(), options_.later_legs.begin(), options_.later_legs.end());
    model = iscwsa::propagate(stations, legs, field);
  }
  // The measured noise (each station's sigma from its estimator and its depth sigma) as plumb's
  // own random terms; the model's terms beside it. A station's sigma that already holds the
  // model's terms counts by its excess over them only (SurveyOptions::station_sigma_beyond_model):
  // a station's model variance does not depend on the stations after it, so the excess of an
  // earlier station is the one it had when it was added.
  std::vector<StationSigma> sigma = sigma_;
  if (model && options_.station_sigma_beyond_model)
    for (std::size_t k = 0; k < sigma.size(); ++k) sigma[k] = beyond_model(sigma[k], model->angle_variance[k]);
  ErrorModel noise_only;
  noise_only.total_b_uT = options_.errors.total_b_uT;
  noise_only.dip_deg = options_.errors.dip_deg;
  noise_only.gravity_mps2 = options_.errors.gravity_mps2;
  const ErrorModel& own = options_.tool_code ? noise_only : options_.errors;
  const PositionUncertainty measured = propagate_uncertainty(geometry_, sigma, own).back();
  const PositionUncertainty measured_random = propagate_uncertainty(geometry_, sigma, noise_only).back();
  const StationSigma& here = sigma.back();
  double inc_var = here.inclination_sd_deg * here.inclination_sd_deg, azi_var = here.azimuth_sd_deg * here.azimuth_sd_deg;
  double inc_random = inc_var, azi_random = azi_var;
  row.uncertainty.covariance = measured.covariance;
  row.random_uncertainty.covariance = measured_random.covariance;
  if (model) {
    row.uncertainty.covariance += model->total.back();
    row.random_uncertainty.covariance += model->random.back();
    const Eigen::Vector2d all = model->angle_variance.back() / (kDeg * kDeg);
    const Eigen::Vector2d random = model->random_angle_variance.back() / (kDeg * kDeg);
    inc_var += all(0), azi_var += all(1), inc_random += random(0), azi_random += random(1);
  }
  describe_covariance(row.uncertainty);
  describe_covariance(row.random_uncertainty);
  row.inclination_total_sd_deg = std::sqrt(inc_var);
  row.azimuth_total_sd_deg = std::sqrt(azi_var);
  row.inclination_random_sd_deg = std::sqrt(inc_random);
  row.azimuth_random_sd_deg = std::sqrt(azi_random);
}

namespace {

// The station as its survey file holds it (plumb/survey/file_precision.hpp): what is computed from
// it is then what a survey read back from its file computes.
Station station_as_filed(Station s) {
  using namespace precision;
  s.t_s = round_decimals(s.t_s, kSecondDecimals);
  s.md_m = round_decimals(s.md_m, kMetreDecimals);
  s.md_sd_m = round_sigma(s.md_sd_m);
  s.inclination_deg = round_decimals(s.inclination_deg, kDegreeDecimals);
  s.inclination_sd_deg = round_sigma(s.inclination_sd_deg);
  s.magnetic_azimuth_deg = round_decimals(s.magnetic_azimuth_deg, kDegreeDecimals);
  s.azimuth_sd_deg = round_sigma(s.azimuth_sd_deg);
  s.total_g_mps2 = round_decimals(s.total_g_mps2, kGravityDecimals);
  s.total_b_uT = round_decimals(s.total_b_uT, kFieldDecimals);
  s.dip_deg = round_decimals(s.dip_deg, kDegreeDecimals);
  s.toolface_deg = round_decimals(s.toolface_deg, kDegreeDecimals);
  s.toolface_sd_deg = round_sigma(s.toolface_sd_deg);
  return s;
}

}  // namespace

const SurveyRow& Survey::add(const Station& given) {
  const Station s = station_as_filed(given);
  const std::string name = "station " + std::to_string(rows_.size()) + " (MD " + number(s.md_m) + " m)";
  if (!std::isfinite(s.md_m)) throw StationError(name + ": measured depth is not a number");
  if (!(std::isfinite(s.inclination_deg) && s.inclination_deg >= 0 && s.inclination_deg <= 180))
    throw StationError(name + ": inclination " + number(s.inclination_deg) + " deg outside [0, 180]");
  if (!std::isfinite(s.magnetic_azimuth_deg) || std::abs(s.magnetic_azimuth_deg) > 720)
    throw StationError(name + ": azimuth " + number(s.magnetic_azimuth_deg) + " deg out of range");
  for (double sd : {s.md_sd_m, s.inclination_sd_deg, s.azimuth_sd_deg})
    if (!(std::isfinite(sd) && sd >= 0)) throw StationError(name + ": standard deviations must be finite and >= 0");
  if (!rows_.empty()) {
    const double previous = rows_.back().station.md_m;
    if (std::abs(s.md_m - previous) <= kDuplicateDepthM)
      throw StationError(name + ": duplicate of station " + std::to_string(rows_.size() - 1) + " (same measured depth)");
    if (s.md_m < previous)
      throw StationError(name + ": measured depth goes backwards (previous station at " + number(previous) + " m)");
  }

  SurveyRow row;
  row.index = static_cast<std::uint32_t>(rows_.size());
  row.station = s;
  row.reference = options_.reference;
  row.azimuth_deg = convert_magnetic_azimuth(s.magnetic_azimuth_deg, options_.reference, options_.north);
  row.field = options_.field;
  const iscwsa::ToolCode* tool = tool_code_at(s.md_m);
  row.error_model = tool ? tool->name : "plumb";
  row.qc = check_station(s.total_g_mps2, s.total_b_uT, s.dip_deg, options_.field, options_.tolerances, options_.checks);
  if (!s.azimuth_valid) row.warning = "azimuth ill-conditioned (near vertical)";

  const StationGeometry here{s.md_m, s.inclination_deg, row.azimuth_deg};
  if (rows_.empty()) {
    row.point.north_m = options_.tie_in.x();
    row.point.east_m = options_.tie_in.y();
    row.point.tvd_m = options_.tie_in.z();
  } else {
    const StationGeometry& a = geometry_.back();
    const PathPoint& prev = rows_.back().point;
    const double course = here.md_m - a.md_m;
    const double i1 = a.inclination_deg * kDeg, a1 = a.azimuth_deg * kDeg;
    const double i2 = here.inclination_deg * kDeg, a2 = here.azimuth_deg * kDeg;
    row.point.dogleg_deg = dogleg_rad(i1, a1, i2, a2) / kDeg;
    // A reversal of direction has no arc (ratio factor infinite): no tool turns 180 deg between stations.
    if (row.point.dogleg_deg > 179.999) throw StationError(name + ": direction reverses from the previous station");
    const Eigen::Vector3d d = course_displacement(course, i1, a1, i2, a2);
    row.point.north_m = prev.north_m + d.x();
    row.point.east_m = prev.east_m + d.y();
    row.point.tvd_m = prev.tvd_m + d.z();
    row.point.dls_deg_per_30m = dls_deg_per_30m(row.point.dogleg_deg, course);
    row.point.dls_deg_per_100ft = dls_deg_per_100ft(row.point.dogleg_deg, course);
  }
  geometry_.push_back(here);
  sigma_.push_back({s.md_sd_m, s.inclination_sd_deg, s.azimuth_sd_deg, s.magnetic_azimuth_deg});
  fill_section_and_closure(row.point, options_.section_azimuth_deg.value_or(0));
  // The uncertainty at this station depends on the stations above it only; the whole propagation
  // is O(stations) and a survey holds hundreds, not millions.
  add_model_uncertainty(row);
  if (!row.qc.pass) ++failed_qc_;
  rows_.push_back(std::move(row));
  if (section_azimuth_is_closure()) {
    // The well's direction moved with this station: every row's section along it (O(stations)).
    const double azimuth = section_azimuth_deg();
    for (auto& r : rows_) fill_section_and_closure(r.point, azimuth);
  }
  return rows_.back();
}

double Survey::section_azimuth_deg() const {
  if (options_.section_azimuth_deg) return *options_.section_azimuth_deg;
  return rows_.empty() ? 0.0 : rows_.back().point.closure_azimuth_deg;
}

PositionUncertainty Survey::uncertainty_between(std::size_t course, double md_m, double inclination_deg,
                                                double azimuth_deg) const {
  if (course + 1 >= rows_.size()) throw std::out_of_range("survey has no course after station " + std::to_string(course));
  const Station& a = rows_[course].station;
  const Station& b = rows_[course + 1].station;
  if (md_m <= a.md_m + kDuplicateDepthM) return rows_[course].uncertainty;
  if (md_m >= b.md_m - kDuplicateDepthM) return rows_[course + 1].uncertainty;
  const double f = (md_m - a.md_m) / (b.md_m - a.md_m);
  const auto lerp = [f](double x, double y) { return x + f * (y - x); };
  Survey above(*this);  // the stations down to the course's start, then the point
  above.rows_.resize(course + 1);
  above.geometry_.resize(course + 1);
  above.sigma_.resize(course + 1);
  Station here;
  here.t_s = lerp(a.t_s, b.t_s);
  here.md_m = md_m;
  here.md_sd_m = lerp(a.md_sd_m, b.md_sd_m);
  here.inclination_deg = inclination_deg;
  here.inclination_sd_deg = lerp(a.inclination_sd_deg, b.inclination_sd_deg);
  // The sensors' azimuth: the survey's less its (constant) correction from magnetic.
  here.magnetic_azimuth_deg = azimuth_deg - (rows_[course].azimuth_deg - a.magnetic_azimuth_deg);
  here.azimuth_sd_deg = lerp(a.azimuth_sd_deg, b.azimuth_sd_deg);
  return above.add(here).uncertainty;
}

}  // namespace plumb::survey
