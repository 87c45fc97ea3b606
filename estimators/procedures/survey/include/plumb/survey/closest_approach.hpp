// Where a well passes closest to a point. Between two stations a well is the minimum-curvature
// arc (the path every survey program draws), so the nearest point is searched along the arcs, not
// only at the stations: an offset well crossing the reference between its stations is found where
// it crosses. A course is a circular arc, so its nearest point has a closed form (no iteration,
// no starting guess, no local minimum missed): the distance to a point on a circle is smallest
// where the point's projection on the circle's plane lies, or at an end of the arc.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace plumb::survey {

// One point of a well: its direction, where it is and how well that is known.
struct WellPoint {
  double md_m = 0;
  double inclination_deg = 0, azimuth_deg = 0;               // the wells' common north (true or grid)
  Eigen::Vector3d position = Eigen::Vector3d::Zero();         // north, east, TVD (m), in a frame all wells share
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();       // north, east, down (m^2)
};

// The point of the course from `a` to `b` at `md_m` (a.md_m <= md_m <= b.md_m): on the arc, with the
// arc's direction there; its covariance interpolated linearly in measured depth between the two
// stations (the error model is evaluated at stations only; between them it grows smoothly).
WellPoint interpolate_course(const WellPoint& a, const WellPoint& b, double md_m);

struct NearestPoint {
  WellPoint point;
  std::size_t course = 0;  // the point lies between stations `course` and `course + 1` (or is station 0)
  double distance_m = 0;
};

// The point of `well` (stations in increasing measured depth, positions from minimum curvature)
// nearest to `p`. Throws std::invalid_argument for a well without stations.
NearestPoint nearest_point(const std::vector<WellPoint>& well, const Eigen::Vector3d& p);

}  // namespace plumb::survey
