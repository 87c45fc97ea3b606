// Minimum curvature: the well path between two survey stations is the circular arc that leaves the
// first station along its direction and arrives at the second along its own (Taylor and Mason,
// SPE 3362, 1972; the method every survey library and contractor uses). Frames: NED of shared
// docs/conventions.md, so "down" is the true vertical depth below the tie-in.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace plumb::survey {

inline constexpr double kFootM = 0.3048;

// Unit tangent of the hole (north, east, down) at inclination and azimuth (radians).
Eigen::Vector3d tangent(double inclination_rad, double azimuth_rad);

// Angle between two station directions, radians in [0, pi]. Haversine form up to 90 deg
// (2 asin sqrt(sin^2(dI/2) + sinI1 sinI2 sin^2(dA/2))), atan2(|t1 x t2|, t1 . t2) beyond: full
// relative precision for doglegs down to 1e-12 rad, where the textbook acos form returns 0.
double dogleg_rad(double inc1_rad, double azi1_rad, double inc2_rad, double azi2_rad);

// Ratio factor RF = (2 / DL) tan(DL / 2), with its series 1 + DL^2/12 + DL^4/120 + 17 DL^6/20160 near
// a straight course (the 0/0 of the closed form). Throws std::domain_error for DL >= pi (no arc).
double ratio_factor(double dogleg_rad);

// Displacement (north, east, down) over a course of length `course_m` between two directions.
Eigen::Vector3d course_displacement(double course_m, double inc1_rad, double azi1_rad, double inc2_rad,
                                    double azi2_rad);

// Dogleg severity from a dogleg (deg) over a course (m): deg/30 m and deg/100 ft.
double dls_deg_per_30m(double dogleg_deg, double course_m);
double dls_deg_per_100ft(double dogleg_deg, double course_m);

// One station's direction along the hole.
struct StationGeometry {
  double md_m = 0;
  double inclination_deg = 0;
  double azimuth_deg = 0;
};

// Where the path is at one station.
struct PathPoint {
  double north_m = 0, east_m = 0, tvd_m = 0;     // from the tie-in's reference point
  double dogleg_deg = 0;                         // of the course ending here (0 at the first station)
  double dls_deg_per_30m = 0, dls_deg_per_100ft = 0;
  double vertical_section_m = 0;                 // horizontal displacement projected on the section azimuth
  double closure_distance_m = 0;                 // horizontal distance from the reference point
  double closure_azimuth_deg = 0;                // its direction, [0, 360), same reference as the azimuths
};

// Horizontal quantities of a point: vertical section along `section_azimuth_deg` and closure.
void fill_section_and_closure(PathPoint& p, double section_azimuth_deg);

// The whole path; the first station sits at `tie_in` (north, east, tvd). Measured depths must
// increase strictly (std::invalid_argument naming the station otherwise).
std::vector<PathPoint> minimum_curvature(const std::vector<StationGeometry>& stations,
                                         const Eigen::Vector3d& tie_in = Eigen::Vector3d::Zero(),
                                         double section_azimuth_deg = 0);

}  // namespace plumb::survey
