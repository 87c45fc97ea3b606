#include "plumb/survey/closest_approach.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "plumb/core/attitude.hpp"
#include "plumb/survey/minimum_curvature.hpp"

namespace plumb::survey {
namespace {

// Below this dogleg a course is drawn as its chord: the arc's sagitta, course x dogleg / 8, is under
// 4e-8 m on a 300 m course, and the circle's radius (course / dogleg) would be too large to carry.
constexpr double kApproachStraightRad = 1e-9;

// One course as a circle arc: it leaves `start` along `along`, turns toward `normal` (unit, normal
// to `along`) over `dogleg` radians with radius `radius`.
struct ApproachArc {
  Eigen::Vector3d start, end, along, normal;
  double dogleg = 0, radius = 0, course = 0;
  bool straight = true;
};

ApproachArc approach_arc(const WellPoint& a, const WellPoint& b) {
  ApproachArc c;
  c.start = a.position;
  c.end = b.position;
  c.course = b.md_m - a.md_m;
  const double i1 = a.inclination_deg * kDeg, a1 = a.azimuth_deg * kDeg;
  const double i2 = b.inclination_deg * kDeg, a2 = b.azimuth_deg * kDeg;
  c.along = tangent(i1, a1);
  c.dogleg = dogleg_rad(i1, a1, i2, a2);
  c.straight = c.dogleg < kApproachStraightRad || !(c.course > 0);
  if (!c.straight) {
    // The part of the second direction normal to the first: the way the arc turns.
    c.normal = (tangent(i2, a2) - std::cos(c.dogleg) * c.along) / std::sin(c.dogleg);
    c.normal.normalize();
    c.radius = c.course / c.dogleg;
  } else {
    c.normal.setZero();
  }
  return c;
}

// Position and direction at arc angle `theta` (0 at the start, `dogleg` at the end).
Eigen::Vector3d approach_arc_position(const ApproachArc& c, double theta) {
  // R (1 - cos t) written as 2 R sin^2(t/2): no cancellation on the gentle arcs of a long radius.
  const double s = std::sin(theta / 2);
  return c.start + 2 * c.radius * s * s * c.normal + c.radius * std::sin(theta) * c.along;
}

double approach_inclination_deg(const Eigen::Vector3d& t) { return std::atan2(std::hypot(t.x(), t.y()), t.z()) / kDeg; }

// The point of a course at fraction `f` of its length, with the stations' values interpolated.
WellPoint approach_point(const WellPoint& a, const WellPoint& b, const ApproachArc& c, double f) {
  WellPoint p;
  f = std::clamp(f, 0.0, 1.0);
  p.md_m = a.md_m + f * c.course;
  p.covariance = a.covariance + f * (b.covariance - a.covariance);
  if (c.straight) {
    p.position = a.position + f * (b.position - a.position);
    p.inclination_deg = a.inclination_deg;
    p.azimuth_deg = a.azimuth_deg;
    return p;
  }
  const double theta = f * c.dogleg;
  p.position = approach_arc_position(c, theta);
  const Eigen::Vector3d t = std::cos(theta) * c.along + std::sin(theta) * c.normal;
  p.inclination_deg = approach_inclination_deg(t);
  // A vertical direction has no azimuth: the start's, as a survey carries it down a vertical hole.
  p.azimuth_deg = std::hypot(t.x(), t.y()) > 1e-12 ? wrap_deg_360(std::atan2(t.y(), t.x()) / kDeg) : a.azimuth_deg;
  return p;
}

// The fraction of the course where it is nearest to `p`.
double approach_nearest_fraction(const ApproachArc& c, const Eigen::Vector3d& p) {
  const Eigen::Vector3d w = p - c.start;
  if (c.straight) {
    const Eigen::Vector3d d = c.end - c.start;
    const double d2 = d.squaredNorm();
    return d2 > 0 ? std::clamp(w.dot(d) / d2, 0.0, 1.0) : 0.0;
  }
  // |p - P(t)|^2 = const - 2 R (u cos t + v sin t) with u = R - w.normal, v = w.along: the distance
  // is smallest where u cos t + v sin t = rho cos(t - phi) is largest, at t = phi on the arc, or
  // else at the end of the arc where that is larger.
  const double u = c.radius - w.dot(c.normal), v = w.dot(c.along);
  const double phi = std::atan2(v, u);
  if (phi >= 0 && phi <= c.dogleg) return phi / c.dogleg;
  const double at_end = u * std::cos(c.dogleg) + v * std::sin(c.dogleg);
  return at_end > u ? 1.0 : 0.0;
}

}  // namespace

WellPoint interpolate_course(const WellPoint& a, const WellPoint& b, double md_m) {
  const ApproachArc c = approach_arc(a, b);
  return approach_point(a, b, c, c.course > 0 ? (md_m - a.md_m) / c.course : 0.0);
}

NearestPoint nearest_point(const std::vector<WellPoint>& well, const Eigen::Vector3d& p) {
  if (well.empty()) throw std::invalid_argument("a well without stations has no nearest point");
  NearestPoint best;
  best.point = well.front();
  best.distance_m = (well.front().position - p).norm();
  for (std::size_t k = 0; k + 1 < well.size(); ++k) {
    const ApproachArc c = approach_arc(well[k], well[k + 1]);
    const WellPoint q = approach_point(well[k], well[k + 1], c, approach_nearest_fraction(c, p));
    const double d = (q.position - p).norm();
    if (d < best.distance_m) {
      best.point = q;
      best.course = k;
      best.distance_m = d;
    }
  }
  return best;
}

}  // namespace plumb::survey
