// The coefficients model: exact inverse of the simulator, the sensors' own temperature terms, the
// second-order root. Its file is tests/unit/csv/coefficients_file_test.cpp.
#include <cmath>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "plumb/core/calibration_model.hpp"
#include "plumb/sim/turntable.hpp"

namespace plumb {
namespace {

// Version 2's sensor terms: the sensor's own scale multiplies its whole output, bias included
// (docs/methods.md section 3: output_i = k_i(T) (a_i + b_i(T) + ...)), before the matrix S.
TEST(CalibrationModel, VersionTwoScaleDriftActsOnTheSensorsOutput) {
  TriadModel t;
  t.sensitivity << 2, 0.1, 0, 0, 2, 0, 0.05, 0, 2;
  t.bias = Eigen::Vector3d(0.1, -0.2, 0.3);
  t.bias_temp2 = Eigen::Vector3d(1e-5, 0, 0);
  t.sensor_scale_temp1 = Eigen::Vector3d(1e-3, -2e-3, 0);
  const double dT = 50;
  const Eigen::Vector3d a(1, -2, 9);
  // The sensor's view: u = s .* (b(dT) + S^-1 a), s = 1 + s1 dT.
  const Eigen::Vector3d s(1 + 1e-3 * dT, 1 - 2e-3 * dT, 1);
  const Eigen::Vector3d b = t.bias + Eigen::Vector3d(1e-5 * dT * dT, 0, 0);
  const Eigen::Vector3d u = s.cwiseProduct(b + t.sensitivity.inverse() * a);
  EXPECT_LT((t.apply(u, dT) - a).norm(), 1e-12);
  EXPECT_LT((t.raw_for(a, dT) - u).norm(), 1e-12);
  EXPECT_TRUE(t.has_version2_terms());
  EXPECT_FALSE(t.is_identity());
}

// The simulator's raw outputs are the exact inverse of the model, including the second-order term
// and the temperature terms: apply() gives back the physical value to rounding.
TEST(CalibrationModel, InvertsTheSimulatedPackage) {
  const auto pkg = sim::SensorPackage::typical(sim::AccelOutput::Voltage, 7);
  for (double T : {-20.0, 25.0, 150.0, 230.0}) {
    const Eigen::Vector3d f(3.1, -7.2, 5.0), b(20, -5, 41);
    Sample s;
    s.f = pkg.raw_accel(f, T);
    s.b = pkg.raw_mag(b, T);
    s.temp_c = pkg.raw_temperature(T);
    s.flags = flags::kHasTemperature;
    pkg.truth.apply(s);
    EXPECT_NEAR(s.temp_c, T, 1e-9);
    EXPECT_LT((s.f - f).norm(), 1e-9 * f.norm());
    EXPECT_LT((s.b - b).norm(), 1e-9 * b.norm());
    EXPECT_TRUE(s.flags & flags::kCalibrated);
    EXPECT_EQ((s.flags & flags::kTemperatureOutOfRange) != 0, T < pkg.truth.temp_min_c || T > pkg.truth.temp_max_c);
  }
}

TEST(CalibrationModel, TemperatureOutsideRangeIsFlaggedAndMissingThermometerUsesReference) {
  CalibrationModel m;
  m.temp_min_c = 0;
  m.temp_max_c = 100;
  m.accelerometer.bias_temp = Eigen::Vector3d(1, 1, 1);
  Sample hot;
  hot.temp_c = 150;
  hot.flags = flags::kHasTemperature;
  m.apply(hot);
  EXPECT_TRUE(hot.flags & flags::kTemperatureOutOfRange);
  EXPECT_NEAR(hot.f.x(), -(150 - 25), 1e-12);  // bias_temp * dT removed
  Sample none;  // no thermometer: calibrated at the reference temperature, not flagged
  m.apply(none);
  EXPECT_FALSE(none.flags & flags::kTemperatureOutOfRange);
  EXPECT_EQ(none.f.x(), 0.0);
}

TEST(CalibrationModel, SecondOrderRootIsTheOneNearTheLinearValue) {
  TriadModel t;
  t.second_order = Eigen::Vector3d(1e-3, -1e-3, 0);
  const Eigen::Vector3d a(9.8, 9.8, 9.8);
  const Eigen::Vector3d w = a + t.second_order.cwiseProduct(a.cwiseAbs2());
  EXPECT_LT((t.apply(w, 0) - a).norm(), 1e-12);
  EXPECT_TRUE(TriadModel{}.is_identity());
  EXPECT_FALSE(t.is_identity());
}

}  // namespace
}  // namespace plumb
