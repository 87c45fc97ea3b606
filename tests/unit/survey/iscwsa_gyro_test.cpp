// The ISCWSA gyro model (SPE 90408; the OWSG gyro tool codes) against what its terms stand for:
// each gyrocompass term is the derivative of the gyrocompass's own closed form with respect to the
// gyro error it names; a continuous run's drift and random walk grow with the time run; a constant
// drift moves a straight horizontal well by the integral of its azimuth error; a known azimuth's
// error rotates the run about the vertical; a gyrocompass initialisation's error is kept by the run.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/survey/iscwsa.hpp"
#include "plumb/survey/minimum_curvature.hpp"
#include "plumb/survey/survey.hpp"
#include "plumb/survey/tool_code_file.hpp"

namespace plumb::survey::iscwsa {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadPerDeg = kPi / 180;
constexpr double kEarthRate = 7.292115e-5 * 3600;  // rad/h

// Stations along a path given by (md, inc, azi) with their minimum-curvature TVD; times in s.
std::vector<Station> stations(const std::vector<StationGeometry>& g, const std::vector<double>& t = {}) {
  const auto path = minimum_curvature(g);
  std::vector<Station> s;
  for (std::size_t k = 0; k < g.size(); ++k)
    s.push_back({g[k].md_m, g[k].inclination_deg, g[k].azimuth_deg, g[k].azimuth_deg, path[k].tvd_m,
                 t.empty() ? std::nan("") : t[k]});
  return s;
}

ToolCode one_term(const std::string& wf, double magnitude, const std::string& unit, Propagation p, GyroRunning r) {
  ToolCode t{wf, 5, 0.000572615, {{wf, wf, magnitude, unit, p}}};
  t.gyro = r;
  return t;
}

Field at_latitude(double latitude_deg) {
  Field f;
  f.latitude_deg = latitude_deg;
  return f;
}

// The earth's rate in the tool's axes (x the high side: toolface 0, rad/h), and the gyrocompasses
// that turn gyro readings into an azimuth: x-y gyros, with the vertical part of the earth's rate
// known from the latitude; and a triad, rotated level by the inclination.
Eigen::Vector3d earth_rate_in_tool(double inc, double azi, double lat) {
  const Eigen::Vector3d level(kEarthRate * std::cos(lat) * std::cos(azi), -kEarthRate * std::cos(lat) * std::sin(azi),
                              -kEarthRate * std::sin(lat));
  Eigen::Matrix3d r2;  // docs/conventions.md R2(I)
  r2 << std::cos(inc), 0, -std::sin(inc), 0, 1, 0, std::sin(inc), 0, std::cos(inc);
  return r2 * level;
}
double xy_gyrocompass(const Eigen::Vector3d& w, double inc, double lat) {
  return std::atan2(-w.y() * std::cos(inc), w.x() - kEarthRate * std::sin(inc) * std::sin(lat));
}
double xyz_gyrocompass(const Eigen::Vector3d& w, double inc, double) {
  const Eigen::Vector3d level(std::cos(inc) * w.x() + std::sin(inc) * w.z(), w.y(), 0);
  return std::atan2(-level.y(), level.x());
}

TEST(IscwsaGyro, GyrocompassTermsAreTheClosedFormsDerivatives) {
  GyroRunning stationary;
  stationary.static_end_inc_deg = 89;
  const auto wrap = [](double a) { return std::remainder(a, 2 * kPi); };
  int checked = 0;
  for (double latitude_deg : {20.0, 60.0}) {
    const double lat = latitude_deg * kRadPerDeg;
    for (double inc_deg : {0.0, 10.0, 35.0, 60.0, 80.0}) {
      for (double azi_deg : {0.0, 30.0, 100.0, 200.0, 310.0}) {
        const double inc = inc_deg * kRadPerDeg, azi = azi_deg * kRadPerDeg;
        const double si = std::sin(inc), ci = std::cos(inc);
        const Eigen::Vector3d w = earth_rate_in_tool(inc, azi, lat);
        // d(azimuth)/d(rate error) on each gyro axis (x high side, y lateral, z the tool axis).
        const auto derivatives = [&](double (*compass)(const Eigen::Vector3d&, double, double)) {
          EXPECT_NEAR(wrap(compass(w, inc, lat) - azi), 0, 1e-12);
          Eigen::Vector3d d;
          for (int a = 0; a < 3; ++a) {
            const Eigen::Vector3d step = 1e-7 * Eigen::Vector3d::Unit(a);
            d(a) = wrap(compass(w + step, inc, lat) - compass(w - step, inc, lat)) / 2e-7;
          }
          return d;
        };
        const Eigen::Vector3d xy = derivatives(xy_gyrocompass), xyz = derivatives(xyz_gyrocompass);
        // Biases (B), errors per g of gravity along the high side (g sinI) and the tool axis
        // (g cosI) (G), noise on the gyros used (RN), and a scale factor on the x-y gyros (SF).
        const struct {
          const char* wf;
          double expected;
        } terms[] = {{"GXY-B1", std::abs(xy.x())},
                     {"GXY-B2", std::abs(xy.y())},
                     {"GXY-G1", std::abs(xy.y()) * si},
                     {"GXY-G2", std::abs(xy.y()) * ci},
                     {"GXY-G3", std::abs(xy.x()) * ci},
                     {"GXY-G4", std::abs(xy.x()) * si},
                     {"GXY-RN", std::hypot(xy.x(), xy.y())},
                     {"GXY-SF", std::abs(xy.x() * w.x() + xy.y() * w.y())},
                     {"GXYZ-XYB1", std::abs(xyz.x())},
                     {"GXYZ-XYB2", std::abs(xyz.y())},
                     {"GXYZ-ZB", std::abs(xyz.z())},
                     {"GXYZ-XYG1", std::abs(xyz.y()) * si},
                     {"GXYZ-XYG2", std::abs(xyz.y()) * ci},
                     {"GXYZ-XYG3", std::abs(xyz.x()) * ci},
                     {"GXYZ-XYG4", std::abs(xyz.x()) * si},
                     {"GXYZ-ZG1", std::abs(xyz.z()) * si},
                     {"GXYZ-ZG2", std::abs(xyz.z()) * ci},
                     {"GXYZ-XYRN", std::hypot(xyz.x(), xyz.y())},
                     {"GXYZ-ZRN", std::abs(xyz.z())}};
        for (const auto& term : terms) {
          // GXY-SF is per unit of scale factor (an error of SF times the rate each gyro reads).
          const bool sf = std::string(term.wf) == "GXY-SF";
          const ToolCode tool = one_term(term.wf, 1.0, sf ? "-" : "deg/hr", Propagation::Systematic, stationary);
          const Result res = propagate(stations({{0, inc_deg, azi_deg}, {30, inc_deg, azi_deg}}), tool, at_latitude(latitude_deg));
          const double weight = std::sqrt(res.angle_variance[1](1)) / (sf ? 1.0 : kRadPerDeg);
          EXPECT_NEAR(weight, term.expected, 1e-6 * term.expected + 1e-9)
              << term.wf << " I " << inc_deg << " A " << azi_deg << " latitude " << latitude_deg;
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 2 * 5 * 5 * 19);
}

GyroRunning continuous_from_a_known_azimuth(double running_speed_m_per_h = 0) {
  GyroRunning r;
  r.static_end_inc_deg = -1;
  r.continuous = true;
  r.initialisation = GyroInitialisation::Reference;
  r.running_speed_m_per_h = running_speed_m_per_h;
  return r;
}

TEST(IscwsaGyro, ContinuousDriftAndRandomWalkGrowWithTheTimeRun) {
  const double inc = 40;
  std::vector<StationGeometry> g;
  std::vector<double> t;
  for (int k = 0; k <= 8; ++k) {
    g.push_back({30.0 * k, inc, 50});
    t.push_back(1800.0 * k);  // half an hour a course
  }
  const double s = std::sin(inc * kRadPerDeg), c = std::cos(inc * kRadPerDeg);
  const struct {
    const char* wf;
    double magnitude;
    const char* unit;
    double (*sd_deg)(double hours, double s, double c);
  } terms[] = {{"GXYZ-GD", 1.0, "deg/hr", [](double h, double, double) { return 1.0 * h; }},
               {"GXY-GD", 1.0, "deg/hr", [](double h, double s, double) { return h / s; }},
               {"GZ-GD", 1.0, "deg/hr", [](double h, double, double c) { return h / c; }},
               {"GXYZ-GRW", 0.1, "deg/sqrt(hr)", [](double h, double, double) { return 0.1 * std::sqrt(h); }},
               {"GXY-GRW", 0.1, "deg/sqr(hr)", [](double h, double s, double) { return 0.1 * std::sqrt(h) / s; }}};
  for (const auto& term : terms) {
    // From the stations' times, and from the course over a running speed of 60 m/h: the same hours.
    for (double speed : {0.0, 60.0}) {
      const ToolCode tool = one_term(term.wf, term.magnitude, term.unit, Propagation::Systematic,
                                     continuous_from_a_known_azimuth(speed));
      const Result r = propagate(stations(g, t), tool, Field{});
      for (std::size_t k = 0; k < g.size(); ++k) {
        const double expected = term.sd_deg(t[k] / 3600, s, c);
        EXPECT_NEAR(std::sqrt(r.angle_variance[k](1)) / kRadPerDeg, expected, 1e-9 * expected + 1e-12)
            << term.wf << " station " << k << " speed " << speed;
      }
    }
  }
}

// A z gyro that hands over to x-y gyros at 17 deg (SPE 90408's Model #4) does so inside the course
// from 16 to 18 deg: each set drifts over its own part of it, as if a station stood at 17 deg.
TEST(IscwsaGyro, AHandOverWithinACourseSharesItAtItsInclination) {
  GyroRunning r = continuous_from_a_known_azimuth(60);
  r.z_drift_from_inc_deg = 0, r.z_drift_to_inc_deg = 17;
  r.xy_drift_from_inc_deg = 17, r.xy_drift_to_inc_deg = 150;
  std::vector<StationGeometry> every_2_deg, and_at_17;
  for (int k = 0; k <= 7; ++k) {
    every_2_deg.push_back({30.0 * k, 10.0 + 2 * k, 50});
    and_at_17.push_back(every_2_deg.back());
    if (k == 3) and_at_17.push_back({105, 17, 50});  // a planar arc: the inclination even along it
  }
  for (const char* wf : {"GZ-GD", "GXY-GD", "GZ-GRW", "GXY-GRW"}) {
    const bool walk = std::string(wf).ends_with("GRW");
    const ToolCode tool = one_term(wf, 1.0, walk ? "deg/sqrt(hr)" : "deg/hr", Propagation::Systematic, r);
    const double a = propagate(stations(every_2_deg), tool, Field{}).angle_variance.back()(1);
    const double b = propagate(stations(and_at_17), tool, Field{}).angle_variance.back()(1);
    EXPECT_GT(a, 0) << wf;
    EXPECT_NEAR(a, b, 1e-12 * b) << wf;
  }
}

TEST(IscwsaGyro, DriftMovesAHorizontalWellByTheIntegralOfItsAzimuthError) {
  // Due north at 90 deg, 1200 m at 100 m/h with 1 deg/h of drift: the azimuth error grows as
  // d s / v, and the well's end moves east by the integral, d L^2 / (2 v).
  std::vector<StationGeometry> g;
  for (int k = 0; k <= 40; ++k) g.push_back({30.0 * k, 90, 0});
  const ToolCode tool = one_term("GXYZ-GD", 1.0, "deg/hr", Propagation::Systematic, continuous_from_a_known_azimuth(100));
  const Result r = propagate(stations(g), tool, Field{});
  for (std::size_t k = 1; k < g.size(); ++k) {
    const double L = g[k].md_m;
    const double east = kRadPerDeg * L * L / (2 * 100);
    EXPECT_NEAR(std::sqrt(r.total[k](1, 1)), east, 1e-9 * east) << "MD " << L;
    EXPECT_NEAR(r.total[k](0, 0), 0, 1e-9 * east * east);
  }
}

TEST(IscwsaGyro, AKnownAzimuthsErrorRotatesTheRunAboutTheVertical) {
  // A build and turn: 3 deg / 30 m from vertical, turning 2 deg / 30 m; EXT-REF 0.5 deg moves each
  // station by 0.5 deg times its horizontal offset, at right angles to it.
  std::vector<StationGeometry> g;
  for (int k = 0; k <= 30; ++k) g.push_back({30.0 * k, 3.0 * k, 20 + 2.0 * k});
  const ToolCode tool = one_term("EXT-REF", 0.5, "deg", Propagation::Systematic, continuous_from_a_known_azimuth(1000));
  const Result r = propagate(stations(g), tool, Field{});
  const auto path = minimum_curvature(g);
  const double d = 0.5 * kRadPerDeg;
  for (std::size_t k = 1; k < g.size(); ++k) {
    const double n = path[k].north_m, e = path[k].east_m;
    const double scale = d * d * (n * n + e * e);
    EXPECT_NEAR(r.total[k](0, 0), d * d * e * e, 1e-3 * scale) << "MD " << g[k].md_m;
    EXPECT_NEAR(r.total[k](1, 1), d * d * n * n, 1e-3 * scale) << "MD " << g[k].md_m;
    EXPECT_NEAR(r.total[k](0, 1), -d * d * n * e, 1e-3 * scale) << "MD " << g[k].md_m;
  }
}

TEST(IscwsaGyro, ARunKeepsTheErrorOfItsGyrocompassInitialisation) {
  // GYRO-NS-CT's running: gyrocompass to 15 deg, then continuous. Vertical to 300 m, then 2 deg
  // per 30 m: 14 deg at 510 m is the last gyrocompass and initialises the run from 16 deg.
  std::vector<StationGeometry> g;
  for (int k = 0; k <= 30; ++k) g.push_back({30.0 * k, k <= 10 ? 0.0 : 2.0 * (k - 10), 70});
  GyroRunning r;
  r.static_end_inc_deg = 15;
  r.continuous = true;
  r.continuous_start_inc_deg = 15;
  r.continuous_end_inc_deg = 150;
  r.running_speed_m_per_h = 2743.2;
  const std::size_t init = 17;  // 14 deg
  ASSERT_EQ(g[init].inclination_deg, 14.0);
  for (const char* wf : {"GXY-B1", "GXY-RN"}) {
    const Result res = propagate(stations(g), one_term(wf, 0.15, "deg/hr", Propagation::Random, r), at_latitude(60));
    for (std::size_t k = init + 1; k < g.size(); ++k)
      EXPECT_NEAR(res.angle_variance[k](1), res.angle_variance[init](1), 1e-15) << wf << " station " << k;
    EXPECT_GT(res.angle_variance[init](1), 0);
  }
  // One draw for the whole run: a random term started at the first station (a gyrocompass at the
  // tie-in, continuous from there) is the same term propagated as systematic.
  GyroRunning from_surface = r;
  from_surface.continuous_start_inc_deg = 0;
  const auto s = stations(g);
  const Result random = propagate(s, one_term("GXY-RN", 0.4, "deg/hr", Propagation::Random, from_surface), at_latitude(60));
  const Result systematic = propagate(s, one_term("GXY-RN", 0.4, "deg/hr", Propagation::Systematic, from_surface), at_latitude(60));
  for (std::size_t k = 1; k < g.size(); ++k)
    EXPECT_LT((random.total[k] - systematic.total[k]).norm(), 1e-12 * (1 + systematic.total[k].norm())) << "station " << k;
  EXPECT_GT(systematic.total.back()(0, 0) + systematic.total.back()(1, 1), 0);
}

TEST(IscwsaGyro, ToolCodesAndTheirFiles) {
  for (const char* name : {"GYRO-NS", "GYRO-NS-CT", "GYRO-MWD", "GYRO:tactical", "GYRO:mems"}) {
    const ToolCode t = builtin_tool_code(name);
    EXPECT_EQ(t.name.rfind(name, 0), 0u) << t.name;
    for (const Term& term : t.terms) EXPECT_TRUE(known_weight_function(term.weight_function)) << name << " " << term.code;
  }
  EXPECT_TRUE(needs_latitude(builtin_tool_code("GYRO-NS")));
  EXPECT_FALSE(needs_latitude(builtin_tool_code("GYRO:tactical")));
  EXPECT_FALSE(needs_latitude(builtin_tool_code("MWD")));
  const ToolCode ct = builtin_tool_code("GYRO-NS-CT");
  EXPECT_TRUE(ct.gyro.continuous);
  EXPECT_EQ(ct.gyro.continuous_start_inc_deg, 15);
  EXPECT_EQ(ct.gyro.running_speed_m_per_h, 2743.2);
  EXPECT_EQ(ct.gyro.noise_reduction_factor, 0.4082);

  std::istringstream file(
      "# a strapdown of one's own\n"
      "# gyro_continuous_inc_deg 0 180\n"
      "# gyro_static_inc_deg 0 0\n"
      "# gyro_initialisation reference\n"
      "# gyro_running_speed_m_per_h 0\n"
      "code,weight_function,magnitude,unit,propagation\n"
      "EXT-REF,EXT-REF,0.3,deg,S\nGXYZ-GD,GXYZ-GD,0.5,deg/hr,S\nGXYZ-GRW,GXYZ-GRW,0.02,deg/sqrt(hr),S\n");
  const ToolCode own = read_tool_code(file, "own.csv");
  EXPECT_TRUE(own.gyro.continuous);
  EXPECT_EQ(own.gyro.initialisation, GyroInitialisation::Reference);
  EXPECT_EQ(own.gyro.static_end_inc_deg, 0);
  ASSERT_EQ(own.terms.size(), 3u);
  std::istringstream bad("# gyro_initialisation magnetic\ncode,weight_function,magnitude,unit,propagation\nEXT-REF,EXT-REF,1,deg,S\n");
  try {
    read_tool_code(bad, "bad.csv");
    FAIL() << "an unknown initialisation was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:1: gyro_initialisation"), std::string::npos) << e.what();
  }
  std::istringstream unknown("# gyro_speed 3\ncode,weight_function,magnitude,unit,propagation\nEXT-REF,EXT-REF,1,deg,S\n");
  EXPECT_THROW(read_tool_code(unknown, "unknown.csv"), std::runtime_error);
}

TEST(IscwsaGyro, WhatTheModelCannotDoIsRefused) {
  std::vector<StationGeometry> g{{0, 30, 10}, {30, 30, 10}, {60, 30, 10}};
  // No latitude for a gyrocompass.
  EXPECT_THROW(propagate(stations(g), builtin_tool_code("GYRO-NS"), Field{}), std::invalid_argument);
  // The stations' times going backwards, without a running speed.
  const ToolCode tactical = builtin_tool_code("GYRO:tactical");
  EXPECT_THROW(propagate(stations(g, {0, 100, 50}), tactical, Field{}), std::invalid_argument);
  // No times at all (a listed survey's 0 everywhere): refused, not a run without drift.
  EXPECT_THROW(propagate(stations(g, {0, 0, 0}), tactical, Field{}), std::invalid_argument);
  EXPECT_NO_THROW(propagate(stations(g, {0, 100, 200}), tactical, Field{}));
  // x-y gyros run continuously through a vertical course.
  std::vector<StationGeometry> vertical{{0, 0, 0}, {30, 0, 0}};
  EXPECT_THROW(propagate(stations(vertical), one_term("GXY-GD", 1, "deg/hr", Propagation::Systematic,
                                                      continuous_from_a_known_azimuth(100)),
                         Field{}),
               std::invalid_argument);
  // A survey with a gyrocompassing tool code and no latitude is refused when it is made.
  SurveyOptions o;
  o.tool_code = builtin_tool_code("GYRO-NS");
  EXPECT_THROW(Survey{o}, std::invalid_argument);
  o.latitude_deg = 60;
  EXPECT_NO_THROW(Survey{o});
}

// A tool code's gyro terms alone (the others are not the subject here: revision 5 counts the first
// course's inclination change twice in its north component only, which is not turned with a frame).
ToolCode gyro_terms_of(const std::string& code) {
  ToolCode t = builtin_tool_code(code);
  std::erase_if(t.terms, [](const Term& term) { return term.weight_function.rfind("GXY", 0) != 0; });
  return t;
}

// A horizontal vector's grid components from its true ones, the grid `convergence_deg` east of true
// north.
Eigen::Matrix3d true_to_grid(double convergence_deg) {
  const double c = std::cos(convergence_deg * kRadPerDeg), s = std::sin(convergence_deg * kRadPerDeg);
  Eigen::Matrix3d r;
  r << c, s, 0, -s, c, 0, 0, 0, 1;
  return r;
}

// A grid survey's positions are a true survey's turned by the convergence, and its gyro errors are
// the true survey's: a gyrocompass reads the earth's rate, which points to true north. So its
// covariance is the true survey's turned with the positions; weighing the grid azimuth instead
// moves it by percents at 3 deg.
TEST(IscwsaGyro, AGridSurveysGyroTermsWeighTheTrueAzimuth) {
  const double convergence_deg = 3;
  const Eigen::Matrix3d to_grid = true_to_grid(convergence_deg);
  // A build to 60 deg, turning from 20 to 80 deg true.
  std::vector<StationGeometry> in_true, in_grid;
  for (int k = 0; k <= 40; ++k) {
    const double inc = std::min(3.0 * k, 60.0), azi = 20 + 1.5 * k;
    in_true.push_back({30.0 * k, inc, azi});
    in_grid.push_back({30.0 * k, inc, azi - convergence_deg});
  }
  for (const char* code : {"GYRO-NS", "GYRO-NS-CT"}) {
    const ToolCode tool = gyro_terms_of(code);
    ASSERT_GE(tool.terms.size(), 5u) << code;
    Field grid = at_latitude(60);
    grid.true_azimuth_offset_deg = convergence_deg;
    const Result t = propagate(stations(in_true), tool, at_latitude(60));
    const Result g = propagate(stations(in_grid), tool, grid);
    const Result grid_weighed = propagate(stations(in_grid), tool, at_latitude(60));
    for (std::size_t k = 1; k < in_true.size(); ++k) {
      const Eigen::Matrix3d expected = to_grid * t.total[k] * to_grid.transpose();
      EXPECT_LT((g.total[k] - expected).norm(), 1e-9 * expected.norm()) << code << " MD " << in_true[k].md_m;
    }
    const Eigen::Matrix3d last = to_grid * t.total.back() * to_grid.transpose();
    EXPECT_GT((grid_weighed.total.back() - last).norm(), 0.01 * last.norm()) << code;
  }
}

// Through a survey: the reference names the frame, the corrections turn it to true north.
TEST(IscwsaGyro, ASurveyInGridGivesItsGyroTermsTheTrueAzimuth) {
  const double convergence_deg = 3;
  const Eigen::Matrix3d to_grid = true_to_grid(convergence_deg);
  std::vector<Eigen::Matrix3d> covariance[2];
  for (int grid = 0; grid < 2; ++grid) {
    SurveyOptions o;
    o.checks = {false, false, false};
    o.tool_code = gyro_terms_of("GYRO-NS");
    o.latitude_deg = 60;
    o.north.declination_deg = -4;
    o.north.declination_known = true;
    o.north.convergence_deg = convergence_deg;
    o.north.convergence_known = grid == 1;
    o.reference = grid ? AzimuthReference::Grid : AzimuthReference::True;
    Survey survey(o);
    for (int k = 0; k <= 20; ++k) {
      survey::Station st;
      st.md_m = 30.0 * k;
      st.inclination_deg = std::min(4.0 * k, 50.0);
      st.magnetic_azimuth_deg = 40 + 2.0 * k;
      survey.add(st);
      covariance[grid].push_back(survey.rows().back().uncertainty.covariance);
    }
  }
  for (std::size_t k = 1; k < covariance[0].size(); ++k) {
    const Eigen::Matrix3d expected = to_grid * covariance[0][k] * to_grid.transpose();
    EXPECT_LT((covariance[1][k] - expected).norm(), 1e-9 * expected.norm()) << "station " << k;
  }
}

TEST(IscwsaGyro, ASurveyOfTheTacticalStrapdownDriftsWithItsTime) {
  SurveyOptions o;
  o.checks = {false, false, false};
  o.tool_code = builtin_tool_code("GYRO:tactical");
  Survey survey(o);
  for (int k = 0; k < 6; ++k) {
    survey::Station s;
    s.t_s = 3600.0 * k;  // a stand an hour
    s.md_m = 500 + 30 * k;
    s.inclination_deg = 30;
    s.magnetic_azimuth_deg = 60;
    survey.add(s);
  }
  const SurveyRow& last = survey.rows().back();
  EXPECT_EQ(last.error_model.rfind("GYRO:tactical", 0), 0u);
  // 5 h at 1 deg/h, the known azimuth's 0.5 deg and the misalignments beside it.
  EXPECT_GT(last.azimuth_total_sd_deg, 5.0);
  EXPECT_LT(last.azimuth_total_sd_deg, 5.2);
}

}  // namespace
}  // namespace plumb::survey::iscwsa
