// Minimum curvature against a published worked example, exact circle geometry, a straight hole,
// reversal of the stations, and an independent implementation (a rotation of the tangent about the
// arc's axis, integrated by Gauss-Legendre quadrature): no number here is copied from a run of plumb.
#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/survey/minimum_curvature.hpp"

namespace plumb::survey {
namespace {

// Published example: "Minimum Curvature Method", drillingformulas.com (after N. J. Lapeyrouse,
// Formulas and Calculations for Drilling, Production and Workover, 2nd ed.): survey 1 at 3500 ft,
// I 15 deg, A 20 deg; survey 2 at 3600 ft, I 25 deg, A 45 deg; dogleg 0.22605 rad = 12.95 deg,
// North 27.22 ft, East 19.45 ft, TVD 94.01 ft. The page prints RF = 1.00408; (2/DL) tan(DL/2) at
// DL = 0.22605 is 1.00428, and only 1.00428 gives the page's own North, East and TVD (1.00408 would
// give 27.21, 19.45, 93.99), so 1.00408 is a transcription slip and the test holds 1.00428.
TEST(MinimumCurvature, PublishedWorkedExample) {
  const double dl = dogleg_rad(15 * kDeg, 20 * kDeg, 25 * kDeg, 45 * kDeg);
  EXPECT_NEAR(dl, 0.22605, 0.000005);
  EXPECT_NEAR(dl / kDeg, 12.95, 0.005);
  EXPECT_NEAR(ratio_factor(dl), 1.00428, 0.000005);
  const std::vector<StationGeometry> s = {{3500 * kFootM, 15, 20}, {3600 * kFootM, 25, 45}};
  const auto path = minimum_curvature(s);
  EXPECT_NEAR(path[1].north_m / kFootM, 27.22, 0.005);
  EXPECT_NEAR(path[1].east_m / kFootM, 19.45, 0.005);
  EXPECT_NEAR(path[1].tvd_m / kFootM, 94.01, 0.005);
  EXPECT_NEAR(path[1].dls_deg_per_100ft, 12.95, 0.005);  // 100 ft course: DLS = dogleg per 100 ft
  EXPECT_NEAR(path[1].dls_deg_per_30m, 12.95 * 30 / 30.48, 0.005);
}

TEST(MinimumCurvature, StraightHoleIsItsTangentTimesLength) {
  for (double inc : {0.0, 10.0, 45.0, 90.0, 135.0}) {
    for (double az : {0.0, 77.0, 300.0}) {
      const std::vector<StationGeometry> s = {{100, inc, az}, {130.5, inc, az}, {400, inc, az}};
      const auto p = minimum_curvature(s);
      const Eigen::Vector3d t = tangent(inc * kDeg, az * kDeg);
      const Eigen::Vector3d end(p[2].north_m, p[2].east_m, p[2].tvd_m);
      EXPECT_NEAR((end - 300 * t).norm(), 0, 1e-12);
      EXPECT_EQ(p[2].dogleg_deg, 0);
      EXPECT_EQ(p[2].dls_deg_per_30m, 0);
    }
  }
}

TEST(MinimumCurvature, SmallDoglegLimitIsContinuous) {
  EXPECT_EQ(ratio_factor(0), 1);
  // Both sides of the series' threshold agree with the closed form to round-off.
  for (double dl : {0.999e-3, 1.001e-3, 1e-2})
    EXPECT_NEAR(ratio_factor(dl), 2 / dl * std::tan(dl / 2), 1e-14) << dl;
  // Tiny doglegs: finite, and the chord formula keeps them (acos would return 0 below ~1e-8).
  // (The step actually represented is i2 - i1, exact by Sterbenz's lemma, not 1e-11.)
  const double i1 = 30 * kDeg, i2 = i1 + 1e-11;
  EXPECT_NEAR(dogleg_rad(i1, 40 * kDeg, i2, 40 * kDeg), i2 - i1, 1e-6 * (i2 - i1));
  const Eigen::Vector3d d = course_displacement(10, 30 * kDeg, 40 * kDeg, 30 * kDeg + 1e-11, 40 * kDeg);
  EXPECT_TRUE(d.allFinite());
  EXPECT_THROW(ratio_factor(kPi), std::domain_error);
}

// A build in the vertical plane of azimuth A at constant radius R from I1 to I2 (exact circle):
// north/east along A by R (cos I1 - cos I2), TVD by R (sin I2 - sin I1), length R (I2 - I1).
TEST(MinimumCurvature, ConstantCurvatureBuildIsAnExactCircle) {
  const double r = 573.0, az = 35 * kDeg;
  for (int n : {2, 3, 17}) {  // any station spacing on the circle gives the same points
    std::vector<StationGeometry> s;
    for (int k = 0; k < n; ++k) {
      const double inc = (10 + 70.0 * k / (n - 1)) * kDeg;
      s.push_back({1000 + r * (inc - 10 * kDeg), inc / kDeg, az / kDeg});
    }
    const auto p = minimum_curvature(s);
    for (int k = 0; k < n; ++k) {
      const double inc = s[static_cast<std::size_t>(k)].inclination_deg * kDeg;
      const double h = r * (std::cos(10 * kDeg) - std::cos(inc));
      const auto& q = p[static_cast<std::size_t>(k)];
      EXPECT_NEAR(q.north_m, h * std::cos(az), 1e-9 * r);
      EXPECT_NEAR(q.east_m, h * std::sin(az), 1e-9 * r);
      EXPECT_NEAR(q.tvd_m, r * (std::sin(inc) - std::sin(10 * kDeg)), 1e-9 * r);
      if (k > 0) {
        EXPECT_NEAR(q.dls_deg_per_30m, 30 / r / kDeg, 1e-9);  // 1/R rad per metre
      }
    }
  }
}

// Gauss-Legendre nodes and weights on [-1, 1] by Newton iteration on the Legendre polynomial.
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(static_cast<std::size_t>(n), 0);
  w.assign(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[static_cast<std::size_t>(i)] = z;
    w[static_cast<std::size_t>(i)] = 2 / ((1 - z * z) * dp * dp);
  }
}

// Independent implementation: the tangent turns at a constant rate about the axis t1 x t2 (the arc
// of minimum curvature); the displacement is the integral of the tangent over the course.
Eigen::Vector3d arc_by_quadrature(double course, const Eigen::Vector3d& t1, const Eigen::Vector3d& t2) {
  std::vector<double> x, w;
  gauss_legendre(24, x, w);
  const Eigen::Vector3d axis = t1.cross(t2);
  const double angle = std::atan2(axis.norm(), t1.dot(t2));
  if (axis.norm() < 1e-15) return course * t1;
  const Eigen::Vector3d k = axis.normalized();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double u = (x[i] + 1) / 2;  // fraction of the course
    sum += w[i] / 2 * (Eigen::AngleAxisd(angle * u, k) * t1);
  }
  return course * sum;
}

TEST(MinimumCurvature, AgreesWithAnIndependentArcIntegrationTo1e9) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> inc(0, 180), az(0, 360), step(0.5, 40);
  double worst = 0;
  for (int run = 0; run < 50; ++run) {
    std::vector<StationGeometry> s;
    double md = 0;
    for (int k = 0; k < 40; ++k) {
      // Doglegs from tiny to large: small steps of the angles, and now and then a jump.
      const double i = k == 0 || k % 7 == 0 ? inc(rng) : std::clamp(s.back().inclination_deg + (inc(rng) - 90) / 30, 0.0, 180.0);
      const double a = k == 0 || k % 5 == 0 ? az(rng) : s.back().azimuth_deg + (az(rng) - 180) / 50;
      s.push_back({md, i, a});
      md += step(rng);
    }
    const auto p = minimum_curvature(s);
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    double length = 0;
    for (std::size_t k = 1; k < s.size(); ++k) {
      const double course = s[k].md_m - s[k - 1].md_m;
      const Eigen::Vector3d t1 = tangent(s[k - 1].inclination_deg * kDeg, s[k - 1].azimuth_deg * kDeg);
      const Eigen::Vector3d t2 = tangent(s[k].inclination_deg * kDeg, s[k].azimuth_deg * kDeg);
      if (std::atan2(t1.cross(t2).norm(), t1.dot(t2)) > 179 * kDeg) continue;  // not generated in practice
      r += arc_by_quadrature(course, t1, t2);
      length += course;
      const Eigen::Vector3d mine(p[k].north_m, p[k].east_m, p[k].tvd_m);
      worst = std::max(worst, (mine - r).norm() / length);
    }
  }
  EXPECT_LT(worst, 1e-9) << "largest difference relative to the length drilled";
}

// Walking the stations backwards (directions reversed: I -> 180 - I, A -> A + 180) retraces the
// same points: the arc between two stations does not depend on the direction of travel.
TEST(MinimumCurvature, ReversedStationsRetraceThePath) {
  std::vector<StationGeometry> s = {{0, 5, 10}, {30, 12, 25}, {61, 30, 60}, {95, 55, 50}, {140, 88, 20}, {170, 91, 15}};
  const auto forward = minimum_curvature(s);
  const double total = s.back().md_m;
  std::vector<StationGeometry> back;
  for (auto it = s.rbegin(); it != s.rend(); ++it) back.push_back({total - it->md_m, 180 - it->inclination_deg, it->azimuth_deg + 180});
  const auto& end = forward.back();
  const auto reverse = minimum_curvature(back, Eigen::Vector3d(end.north_m, end.east_m, end.tvd_m));
  for (std::size_t k = 0; k < s.size(); ++k) {
    const auto& f = forward[k];
    const auto& r = reverse[s.size() - 1 - k];
    EXPECT_NEAR(f.north_m, r.north_m, 1e-10 * total);
    EXPECT_NEAR(f.east_m, r.east_m, 1e-10 * total);
    EXPECT_NEAR(f.tvd_m, r.tvd_m, 1e-10 * total);
    if (k > 0) {
      EXPECT_NEAR(f.dogleg_deg, reverse[s.size() - k].dogleg_deg, 1e-9);
    }
  }
}

TEST(MinimumCurvature, SectionClosureAndUnits) {
  PathPoint p;
  p.north_m = 3;
  p.east_m = 4;
  fill_section_and_closure(p, 90);
  EXPECT_NEAR(p.vertical_section_m, 4, 1e-12);
  EXPECT_NEAR(p.closure_distance_m, 5, 1e-12);
  EXPECT_NEAR(p.closure_azimuth_deg, std::atan2(4, 3) / kDeg, 1e-12);
  fill_section_and_closure(p, 180);
  EXPECT_NEAR(p.vertical_section_m, -3, 1e-12);
  // 100 ft is 30.48 m: the same curvature is 30.48/30 times larger per 100 ft than per 30 m.
  EXPECT_NEAR(dls_deg_per_100ft(3, 30), 3 * 30.48 / 30, 1e-12);
  EXPECT_NEAR(dls_deg_per_30m(3, 30), 3, 1e-12);
}

TEST(MinimumCurvature, DepthMustIncrease) {
  EXPECT_THROW(minimum_curvature({{100, 10, 10}, {100, 11, 10}}), std::invalid_argument);
  EXPECT_THROW(minimum_curvature({{100, 10, 10}, {90, 11, 10}}), std::invalid_argument);
}

}  // namespace
}  // namespace plumb::survey
