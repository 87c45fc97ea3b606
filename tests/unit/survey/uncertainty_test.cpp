// Position uncertainty: exact identities of the systematic terms (a declination error turns the
// whole path about the vertical through the tie-in; a depth scale error stretches it), and a Monte
// Carlo of the random terms that perturbs the stations and recomputes the path independently.
#include <cmath>
#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"
#include "plumb/survey/uncertainty.hpp"


namespace plumb::survey {
namespace {

std::vector<StationGeometry> build_and_turn() {
  std::vector<StationGeometry> s;
  for (int k = 0; k <= 30; ++k) s.push_back({100.0 + 9.5 * k, std::min(5.0 + 3.0 * k, 88.0), 40.0 + 1.5 * k});
  return s;
}

Eigen::Vector3d end_of(const std::vector<StationGeometry>& s) {
  const auto p = minimum_curvature(s);
  return {p.back().north_m, p.back().east_m, p.back().tvd_m};
}

TEST(Uncertainty, DeclinationTurnsThePathAboutTheVertical) {
  const auto s = build_and_turn();
  ErrorModel m;
  m.declination_sd_deg = 0.5;
  const auto u = propagate_uncertainty(s, std::vector<StationSigma>(s.size()), m);
  const Eigen::Vector3d r = end_of(s);
  // A common azimuth change d moves the end by d x (-east, north, 0): exactly a covariance
  // sigma^2 v v^T with v = (-E, N, 0).
  const Eigen::Vector3d v = m.declination_sd_deg * kDeg * Eigen::Vector3d(-r.y(), r.x(), 0);
  const Eigen::Matrix3d expected = v * v.transpose();
  EXPECT_LT((u.back().covariance - expected).norm(), 1e-8 * expected.norm());
  EXPECT_NEAR(u.back().major_sd_m, v.norm(), 1e-8 * v.norm());
  EXPECT_NEAR(u.back().minor_sd_m, 0, 1e-6);
}

TEST(Uncertainty, DepthScaleStretchesThePath) {
  auto s = build_and_turn();
  for (auto& st : s) st.md_m -= 100;  // md from the tie-in: a scale error stretches about it
  ErrorModel m;
  m.depth_scale_sd = 1e-3;
  const auto u = propagate_uncertainty(s, std::vector<StationSigma>(s.size()), m);
  const Eigen::Vector3d v = m.depth_scale_sd * end_of(s);
  EXPECT_LT((u.back().covariance - v * v.transpose()).norm(), 1e-8 * v.squaredNorm());
}

// ABZ: a bias b on the axial accelerometer, put through the closed-form attitude at every station
// (G and B from the frames of docs/conventions.md, b added to Gz), moves the end of the path by a vector
// v b; the propagation must report sigma^2 v v^T for that term. Also the textbook inclination
// sensitivity: I = atan2(g sinI, g cosI + b) gives dI/db = -sinI/g.
TEST(Uncertainty, AxialAccelerometerBiasMatchesTheClosedForm) {
  const auto s = build_and_turn();
  ErrorModel m;
  m.axial_accel_bias_sd_mps2 = 0.003;
  std::vector<StationSigma> sigma;
  for (const auto& st : s) sigma.push_back({0, 0, 0, st.azimuth_deg});
  const auto u = propagate_uncertainty(s, sigma, m);
  const double b = 1e-4;
  auto biased = s;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double inc = s[k].inclination_deg * kDeg, az = s[k].azimuth_deg * kDeg, tf = (37.0 * k) * kDeg;
    const Eigen::Vector3d G = gravity_tool(inc, tf, m.gravity_mps2) + Eigen::Vector3d(0, 0, b);
    const ClosedForm r = closed_form_attitude(G, field_tool(inc, az, tf, m.total_b_uT, m.dip_deg * kDeg));
    biased[k].inclination_deg = r.inclination_deg;
    biased[k].azimuth_deg = r.azimuth_deg;
    EXPECT_NEAR((r.inclination_deg - s[k].inclination_deg) * kDeg, -std::sin(inc) / m.gravity_mps2 * b, 1e-3 * b);
  }
  const Eigen::Vector3d v = (end_of(biased) - end_of(s)) / b * m.axial_accel_bias_sd_mps2;
  EXPECT_LT((u.back().covariance - v * v.transpose()).norm(), 1e-3 * v.squaredNorm());
}

TEST(Uncertainty, FirstStationHasNoneAndTheEllipseDescribesTheCovariance) {
  const auto s = build_and_turn();
  std::vector<StationSigma> sigma(s.size(), StationSigma{0.05, 0.1, 0.5, 0});
  const auto u = propagate_uncertainty(s, sigma, {});
  EXPECT_EQ(u.front().covariance.norm(), 0);
  for (std::size_t k = 2; k < u.size(); ++k) {
    // Random errors only add up: the uncertainty never shrinks down the hole.
    EXPECT_GE(u[k].covariance.trace(), u[k - 1].covariance.trace() * 0.999);
    const Eigen::Matrix2d c = u[k].covariance.topLeftCorner<2, 2>();
    EXPECT_NEAR(u[k].major_sd_m * u[k].major_sd_m + u[k].minor_sd_m * u[k].minor_sd_m, c.trace(), 1e-9 * c.trace());
    EXPECT_NEAR(u[k].major_sd_m * u[k].minor_sd_m, std::sqrt(c.determinant()), 1e-6 * c.trace());
  }
}

// The random terms: draw every station's errors, recompute the path with minimum_curvature (not
// with the propagation's derivatives), and compare the sample covariance of the end position and
// the coverage of the 95 % ellipse with what propagate_uncertainty reports.
TEST(Uncertainty, MonteCarloOfStationErrorsMatchesThePropagation) {
  const auto s = build_and_turn();
  std::vector<StationSigma> sigma;
  for (std::size_t k = 0; k < s.size(); ++k) sigma.push_back({0.05 + 0.01 * k, 0.1, 0.4 + 0.02 * k, s[k].azimuth_deg});
  ErrorModel m;
  m.declination_sd_deg = 0.3;  // systematic: one draw per run, common to every station
  const auto u = propagate_uncertainty(s, sigma, m);
  const Eigen::Vector3d truth = end_of(s);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n01;
  const int runs = 4000;
  Eigen::Matrix3d sample = Eigen::Matrix3d::Zero();
  int inside = 0;
  for (int run = 0; run < runs; ++run) {
    auto p = s;
    const double dec = m.declination_sd_deg * n01(rng);
    double md_error = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      md_error = sigma[k].md_sd_m * n01(rng);  // a reading error of this station's depth
      p[k].md_m += md_error;
      p[k].inclination_deg += sigma[k].inclination_sd_deg * n01(rng);
      p[k].azimuth_deg += sigma[k].azimuth_sd_deg * n01(rng) + dec;
    }
    const Eigen::Vector3d e = end_of(p) - truth;
    sample += e * e.transpose();
    if (inside_ellipse(u.back(), e.x(), e.y(), kEllipse95Factor)) ++inside;
  }
  sample /= runs;
  const Eigen::Matrix3d& c = u.back().covariance;
  // Sample variances of 4000 draws scatter by sqrt(2/4000) = 2.2 %; 8 % is well outside chance.
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(sample(i, i) / c(i, i), 1.0, 0.08) << "axis " << i;
  const double coverage = static_cast<double>(inside) / runs;
  // Binomial sd of the coverage at 95 %: sqrt(0.95 * 0.05 / 4000) = 0.34 %.
  EXPECT_NEAR(coverage, 0.95, 0.015);
  RecordProperty("coverage_95_ellipse", std::to_string(coverage));
  std::printf("end-of-survey error inside the reported 95 %% ellipse in %.1f %% of %d runs\n", 100 * coverage, runs);
}

}  // namespace
}  // namespace plumb::survey
