#include "plumb/survey/minimum_curvature.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include "plumb/core/attitude.hpp"

namespace plumb::survey {

Eigen::Vector3d tangent(double inc, double azi) {
  return {std::sin(inc) * std::cos(azi), std::sin(inc) * std::sin(azi), std::cos(inc)};
}

double dogleg_rad(double inc1, double azi1, double inc2, double azi2) {
  // Haversine form from the angle differences themselves: full relative precision for tiny doglegs
  // (the unit tangents' components carry 1e-16 absolute round-off, 1e-5 relative at 1e-11 rad).
  const double si = std::sin((inc2 - inc1) / 2), sa = std::sin((azi2 - azi1) / 2);
  const double h = si * si + std::sin(inc1) * std::sin(inc2) * sa * sa;
  if (h < 0.5) return 2 * std::asin(std::sqrt(std::max(0.0, h)));
  // Beyond 90 deg asin loses precision near its top; atan2 of the tangents is accurate there.
  const Eigen::Vector3d t1 = tangent(inc1, azi1), t2 = tangent(inc2, azi2);
  return std::atan2(t1.cross(t2).norm(), t1.dot(t2));
}

double ratio_factor(double dl) {
  if (!(dl >= 0) || dl >= kPi) throw std::domain_error("dogleg of " + std::to_string(dl / kDeg) + " deg: no minimum-curvature arc");
  // Below 1e-3 rad the series' first omitted term (31 DL^8 / 362880) is under 1e-28: exact to round-off.
  if (dl < 1e-3) {
    const double d2 = dl * dl;
    return 1 + d2 / 12 + d2 * d2 / 120 + 17 * d2 * d2 * d2 / 20160;
  }
  return 2 / dl * std::tan(dl / 2);
}

Eigen::Vector3d course_displacement(double course_m, double inc1, double azi1, double inc2, double azi2) {
  const double rf = ratio_factor(dogleg_rad(inc1, azi1, inc2, azi2));
  return course_m / 2 * rf * (tangent(inc1, azi1) + tangent(inc2, azi2));
}

double dls_deg_per_30m(double dogleg_deg, double course_m) { return course_m > 0 ? dogleg_deg / course_m * 30 : 0; }
double dls_deg_per_100ft(double dogleg_deg, double course_m) {
  return course_m > 0 ? dogleg_deg / course_m * (100 * kFootM) : 0;
}

void fill_section_and_closure(PathPoint& p, double section_azimuth_deg) {
  const double s = section_azimuth_deg * kDeg;
  p.vertical_section_m = p.north_m * std::cos(s) + p.east_m * std::sin(s);
  p.closure_distance_m = std::hypot(p.north_m, p.east_m);
  p.closure_azimuth_deg = p.closure_distance_m > 0 ? wrap_deg_360(std::atan2(p.east_m, p.north_m) / kDeg) : 0;
}

std::vector<PathPoint> minimum_curvature(const std::vector<StationGeometry>& stations, const Eigen::Vector3d& tie_in,
                                         double section_azimuth_deg) {
  std::vector<PathPoint> path;
  path.reserve(stations.size());
  Eigen::Vector3d r = tie_in;
  for (std::size_t k = 0; k < stations.size(); ++k) {
    PathPoint p;
    if (k > 0) {
      const auto& a = stations[k - 1];
      const auto& b = stations[k];
      const double course = b.md_m - a.md_m;
      if (!(course > 0))
        throw std::invalid_argument("station " + std::to_string(k) + ": measured depth " + std::to_string(b.md_m) +
                                    " m does not increase (previous " + std::to_string(a.md_m) + " m)");
      const double i1 = a.inclination_deg * kDeg, a1 = a.azimuth_deg * kDeg;
      const double i2 = b.inclination_deg * kDeg, a2 = b.azimuth_deg * kDeg;
      r += course_displacement(course, i1, a1, i2, a2);
      p.dogleg_deg = dogleg_rad(i1, a1, i2, a2) / kDeg;
      p.dls_deg_per_30m = dls_deg_per_30m(p.dogleg_deg, course);
      p.dls_deg_per_100ft = dls_deg_per_100ft(p.dogleg_deg, course);
    }
    p.north_m = r.x();
    p.east_m = r.y();
    p.tvd_m = r.z();
    fill_section_and_closure(p, section_azimuth_deg);
    path.push_back(p);
  }
  return path;
}

}  // namespace plumb::survey
