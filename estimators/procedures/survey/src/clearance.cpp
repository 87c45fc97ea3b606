#include "plumb/survey/clearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "plumb/core/attitude.hpp"

namespace plumb::survey {
namespace {

// Closer than this the centre-to-centre line has no direction worth the name.
constexpr double kClearanceSameCentreM = 1e-9;

// A well's 1-sigma extent along the unit vector u: the pedal curve (support function) of its
// 1-sigma ellipsoid, sqrt(u' C u).
double clearance_pedal_radius(const Eigen::Matrix3d& c, const Eigen::Vector3d& u) {
  return std::sqrt(std::max(0.0, u.dot(c * u)));
}

// Without a direction: the ellipsoid's largest semi-axis, the most the well can be off that way.
double clearance_largest_axis(const Eigen::Matrix3d& c) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (c + c.transpose()), Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()));
}

}  // namespace

void check_rule(const SeparationRule& r) {
  if (!(std::isfinite(r.k) && r.k > 0)) throw std::invalid_argument("separation rule: k must be > 0");
  if (!(std::isfinite(r.sigma_pa_m) && r.sigma_pa_m >= 0))
    throw std::invalid_argument("separation rule: the projection-ahead sigma must be >= 0");
  if (!(std::isfinite(r.surface_margin_m) && r.surface_margin_m >= 0))
    throw std::invalid_argument("separation rule: the surface margin must be >= 0");
}

StationClearance station_clearance(const WellPoint& reference, double reference_radius_m, const ClearanceWell& offset,
                                   const SeparationRule& rule) {
  check_rule(rule);
  if (offset.stations.empty()) throw std::invalid_argument("offset well '" + offset.name + "' has no stations");
  StationClearance s;
  s.reference = reference;
  const NearestPoint near = nearest_point(offset.stations, reference.position);
  s.offset = near.point;
  const bool between = near.course + 1 < offset.stations.size() &&
                       near.point.md_m > offset.stations[near.course].md_m + kDuplicateDepthM &&
                       near.point.md_m < offset.stations[near.course + 1].md_m - kDuplicateDepthM;
  if (between && offset.covariance_between) s.offset.covariance = offset.covariance_between(near.course, near.point);
  s.centre_to_centre_m = near.distance_m;
  const Eigen::Vector3d d = s.offset.position - reference.position;
  if (s.centre_to_centre_m > kClearanceSameCentreM) {
    const Eigen::Vector3d u = d / s.centre_to_centre_m;
    s.reference_sigma_m = clearance_pedal_radius(reference.covariance, u);
    s.offset_sigma_m = clearance_pedal_radius(s.offset.covariance, u);
    s.horizontal_bearing_deg = std::hypot(u.x(), u.y()) > 0 ? wrap_deg_360(std::atan2(u.y(), u.x()) / kDeg) : 0;
    const double inc = reference.inclination_deg * kDeg, azi = reference.azimuth_deg * kDeg;
    // Near vertical the high side is the azimuth's direction; a vertical hole's azimuth may be 0.
    const Eigen::Vector3d high(std::cos(inc) * std::cos(azi), std::cos(inc) * std::sin(azi), -std::sin(inc));
    const Eigen::Vector3d lateral(-std::sin(azi), std::cos(azi), 0);
    s.high_side_bearing_deg = wrap_deg_360(std::atan2(u.dot(lateral), u.dot(high)) / kDeg);
  } else {
    s.reference_sigma_m = clearance_largest_axis(reference.covariance);
    s.offset_sigma_m = clearance_largest_axis(s.offset.covariance);
  }
  s.sigma_s_m = std::hypot(s.reference_sigma_m, s.offset_sigma_m);
  s.boundary_m = rule.k * std::hypot(s.sigma_s_m, rule.sigma_pa_m);
  s.separation_m = s.centre_to_centre_m - reference_radius_m - offset.radius_m - rule.surface_margin_m;
  s.masd_m = reference_radius_m + offset.radius_m + rule.surface_margin_m + s.boundary_m;
  s.ellipse_separation_m = s.centre_to_centre_m - s.masd_m;
  // A zero boundary (no uncertainty at all and no projection ahead) leaves only the distance: SF infinite or -infinite.
  s.separation_factor = s.boundary_m > 0 ? s.separation_m / s.boundary_m
                                         : std::copysign(std::numeric_limits<double>::infinity(), s.separation_m);
  return s;
}

std::vector<StationClearance> clearance(const ClearanceWell& reference, const ClearanceWell& offset,
                                        const SeparationRule& rule) {
  std::vector<StationClearance> out;
  out.reserve(reference.stations.size());
  for (const WellPoint& p : reference.stations) out.push_back(station_clearance(p, reference.radius_m, offset, rule));
  return out;
}

WellPoint well_point(const SurveyRow& r) {
  return {r.station.md_m, r.station.inclination_deg, r.azimuth_deg,
          Eigen::Vector3d(r.point.north_m, r.point.east_m, r.point.tvd_m), r.uncertainty.covariance};
}

std::vector<WellPoint> well_points(const std::vector<SurveyRow>& rows) {
  std::vector<WellPoint> out;
  out.reserve(rows.size());
  for (const SurveyRow& r : rows) out.push_back(well_point(r));
  return out;
}

ClearanceWell clearance_well(const Survey& survey, std::string name, double radius_m) {
  auto kept = std::make_shared<const Survey>(survey);
  ClearanceWell w{std::move(name), well_points(kept->rows()), radius_m, {}};
  w.covariance_between = [kept](std::size_t course, const WellPoint& p) {
    return kept->uncertainty_between(course, p.md_m, p.inclination_deg, p.azimuth_deg).covariance;
  };
  return w;
}

void check_levels(const ClearanceLevels& l) {
  if (!(std::isfinite(l.warning_sf) && std::isfinite(l.alarm_sf) && l.warning_sf >= l.alarm_sf))
    throw std::invalid_argument("clearance levels: the warning SF must be finite and at least the alarm SF");
}

ClearanceLevel clearance_level(double sf, const ClearanceLevels& l) {
  if (!(sf >= l.alarm_sf)) return ClearanceLevel::Alarm;  // NaN is no clearance shown: the alarm
  if (sf < l.warning_sf) return ClearanceLevel::Warning;
  return ClearanceLevel::Clear;
}

std::string to_string(ClearanceLevel level) {
  switch (level) {
    case ClearanceLevel::Clear:
      return "clear";
    case ClearanceLevel::Warning:
      return "warning";
    case ClearanceLevel::Alarm:
      return "alarm";
  }
  return "alarm";
}

}  // namespace plumb::survey
