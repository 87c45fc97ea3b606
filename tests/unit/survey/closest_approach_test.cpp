// The nearest point of a well along its minimum-curvature arcs: the closed form against a search
// of each arc (dense samples, then a golden-section refinement), and the interpolated point
// against minimum curvature itself.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/survey/closest_approach.hpp"
#include "plumb/survey/minimum_curvature.hpp"

namespace plumb::survey {
namespace {

// A random well: 30 m courses turning up to 8 deg each, positions by minimum curvature.
std::vector<WellPoint> random_well(std::mt19937& rng) {
  std::uniform_real_distribution<double> turn(-8, 8);
  std::vector<StationGeometry> g{{0, 0, 0}};
  double inc = 0, azi = 37;
  for (int k = 1; k < 40; ++k) {
    inc = std::clamp(inc + std::abs(turn(rng)), 0.0, 170.0);
    azi += turn(rng);
    g.push_back({30.0 * k, inc, wrap_deg_360(azi)});
  }
  const auto path = minimum_curvature(g, {5, -3, 0});
  std::vector<WellPoint> w;
  for (std::size_t k = 0; k < g.size(); ++k)
    w.push_back({g[k].md_m, g[k].inclination_deg, g[k].azimuth_deg,
                 Eigen::Vector3d(path[k].north_m, path[k].east_m, path[k].tvd_m), Eigen::Matrix3d::Zero()});
  return w;
}

// The distance from p to the nearest point of one course, by search.
double searched_distance(const WellPoint& a, const WellPoint& b, const Eigen::Vector3d& p) {
  const auto d = [&](double md) { return (interpolate_course(a, b, md).position - p).norm(); };
  const int n = 400;
  const double step = (b.md_m - a.md_m) / n;
  int best = 0;
  for (int i = 1; i <= n; ++i)
    if (d(a.md_m + i * step) < d(a.md_m + best * step)) best = i;
  double lo = a.md_m + std::max(0, best - 1) * step, hi = a.md_m + std::min(n, best + 1) * step;
  const double r = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 80; ++i) {
    const double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
    if (d(x1) < d(x2))
      hi = x2;
    else
      lo = x1;
  }
  return d((lo + hi) / 2);
}

TEST(ClosestApproach, ClosedFormFindsTheNearestPointOfEveryArc) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> offset(-60, 60);
  for (int trial = 0; trial < 20; ++trial) {
    const auto well = random_well(rng);
    const Eigen::Vector3d p = well[static_cast<std::size_t>(trial) % well.size()].position +
                              Eigen::Vector3d(offset(rng), offset(rng), offset(rng));
    double searched = 1e300;
    for (std::size_t k = 0; k + 1 < well.size(); ++k) searched = std::min(searched, searched_distance(well[k], well[k + 1], p));
    const NearestPoint near = nearest_point(well, p);
    EXPECT_NEAR(near.distance_m, searched, 1e-7) << "trial " << trial;
    EXPECT_NEAR((near.point.position - p).norm(), near.distance_m, 1e-12);
  }
}

TEST(ClosestApproach, InterpolatedPointIsOnTheMinimumCurvaturePath) {
  const WellPoint a{1000, 20, 40, Eigen::Vector3d(10, 20, 900), Eigen::Matrix3d::Identity()};
  WellPoint b{1030, 26, 52, Eigen::Vector3d::Zero(), 3 * Eigen::Matrix3d::Identity()};
  b.position = a.position + course_displacement(30, 20 * kDeg, 40 * kDeg, 26 * kDeg, 52 * kDeg);
  EXPECT_LT((interpolate_course(a, b, 1030).position - b.position).norm(), 1e-9);
  const WellPoint m = interpolate_course(a, b, 1012);
  // The arc from a to the interpolated point is the same arc: minimum curvature to it lands on it.
  const Eigen::Vector3d to_m =
      a.position + course_displacement(12, 20 * kDeg, 40 * kDeg, m.inclination_deg * kDeg, m.azimuth_deg * kDeg);
  EXPECT_LT((m.position - to_m).norm(), 1e-9);
  EXPECT_NEAR(m.covariance(0, 0), 1 + 2 * 12.0 / 30, 1e-12);
  // And on to b from there.
  const Eigen::Vector3d to_b =
      m.position + course_displacement(18, m.inclination_deg * kDeg, m.azimuth_deg * kDeg, 26 * kDeg, 52 * kDeg);
  EXPECT_LT((to_b - b.position).norm(), 1e-9);
}

TEST(ClosestApproach, StraightCourseAndSingleStation) {
  const WellPoint a{0, 90, 0, Eigen::Vector3d(0, 0, 100), Eigen::Matrix3d::Zero()};
  const WellPoint b{100, 90, 0, Eigen::Vector3d(100, 0, 100), Eigen::Matrix3d::Zero()};
  const NearestPoint n = nearest_point({a, b}, Eigen::Vector3d(40, 3, 96));
  EXPECT_NEAR(n.point.md_m, 40, 1e-9);
  EXPECT_NEAR(n.distance_m, 5, 1e-9);
  EXPECT_NEAR(nearest_point({a}, Eigen::Vector3d(3, 4, 100)).distance_m, 5, 1e-12);
  EXPECT_THROW(nearest_point({}, Eigen::Vector3d::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace plumb::survey
