// Closed-form attitude against the frame definitions of docs/conventions.md.
#include <cmath>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "plumb/core/attitude.hpp"

namespace plumb {
namespace {

TEST(Frames, RotationsAreProperAndComposeTheDefinition) {
  for (double a : {-2.0, 0.3, 1.7}) {
    for (const auto& r : {rot1(a), rot2(a), rot3(a)}) {
      EXPECT_NEAR((r * r.transpose() - Eigen::Matrix3d::Identity()).norm(), 0, 1e-14);
      EXPECT_NEAR(r.determinant(), 1, 1e-14);
    }
  }
  const double i = 0.4, az = 2.1, tf = -0.7;
  EXPECT_NEAR((c_nb(i, az, tf) - rot3(tf) * rot2(i) * rot3(az)).norm(), 0, 1e-15);
  // G = C_n^b (0, 0, g) equals the component form of docs/conventions.md.
  EXPECT_NEAR((c_nb(i, az, tf) * Eigen::Vector3d(0, 0, 9.8) - gravity_tool(i, tf, 9.8)).norm(), 0, 1e-12);
}

TEST(ClosedForm, RecoversEveryAttitudeOfAGrid) {
  const double g = 9.81, b = 48.4, dip = 45.5 * kDeg;
  for (double inc : {0.5, 1.0, 5.0, 30.0, 89.0, 90.0, 120.0, 179.0}) {
    for (double az = 0; az < 360; az += 15) {
      for (double tf = 0; tf < 360; tf += 30) {
        const Eigen::Vector3d G = gravity_tool(inc * kDeg, tf * kDeg, g);
        const Eigen::Vector3d B = field_tool(inc * kDeg, az * kDeg, tf * kDeg, b, dip);
        const ClosedForm r = closed_form_attitude(G, B);
        ASSERT_TRUE(r.valid && r.azimuth_valid && r.toolface_valid);
        EXPECT_NEAR(r.inclination_deg, inc, 1e-9);
        EXPECT_NEAR(wrap_deg_180(r.azimuth_deg - az), 0, 1e-8) << inc << " " << az << " " << tf;
        EXPECT_NEAR(wrap_deg_180(r.gravity_toolface_deg - tf), 0, 1e-8);
        EXPECT_NEAR(r.dip_deg, 45.5, 1e-9);
        EXPECT_NEAR(r.total_g, g, 1e-12);
        EXPECT_NEAR(r.total_b, b, 1e-12);
      }
    }
  }
}

TEST(ClosedForm, MagneticToolfaceIsAzimuthPlusToolfaceWhenVertical) {
  // M = A + T exactly at I = 0, where A and T separately are undefined.
  for (double az : {10.0, 100.0, 250.0}) {
    for (double tf : {0.0, 45.0, 300.0}) {
      const Eigen::Vector3d B = field_tool(0, az * kDeg, tf * kDeg, 50, 60 * kDeg);
      const ClosedForm r = closed_form_attitude(gravity_tool(0, tf * kDeg, 9.81), B);
      EXPECT_NEAR(wrap_deg_180(r.magnetic_toolface_deg - (az + tf)), 0, 1e-9);
      EXPECT_TRUE(r.valid);
      EXPECT_FALSE(r.toolface_valid);
      EXPECT_FALSE(r.azimuth_valid);
      EXPECT_FALSE(r.reason.empty());
    }
  }
}

TEST(ClosedForm, BadInputIsFlaggedNeverNaN) {
  const Eigen::Vector3d G(0.1, 0.2, 9.8), B(20, 5, 40);
  const Eigen::Vector3d nan(std::nan(""), 0, 0);
  for (const auto& r : {closed_form_attitude(nan, B), closed_form_attitude(G, nan),
                        closed_form_attitude(Eigen::Vector3d::Zero(), B), closed_form_attitude(G, Eigen::Vector3d::Zero())}) {
    EXPECT_FALSE(r.valid);
    EXPECT_FALSE(r.reason.empty());
    for (double v : {r.inclination_deg, r.azimuth_deg, r.gravity_toolface_deg, r.magnetic_toolface_deg, r.dip_deg})
      EXPECT_TRUE(std::isfinite(v));
  }
}

TEST(Angles, WrapIntoTheirRanges) {
  EXPECT_DOUBLE_EQ(wrap_deg_360(-10), 350);
  EXPECT_DOUBLE_EQ(wrap_deg_360(720), 0);
  EXPECT_DOUBLE_EQ(wrap_deg_180(190), -170);
  EXPECT_DOUBLE_EQ(wrap_deg_180(-180), 180);
  EXPECT_GE(wrap_deg_360(-1e-18), 0.0);
  EXPECT_LT(wrap_deg_360(-1e-18), 360.0);
}

}  // namespace
}  // namespace plumb
