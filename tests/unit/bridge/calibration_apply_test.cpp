// The bridge's calibration path: coefficients from the topic become the same model field for
// field, and applying it inverts the sensor model (raw = S^-1 f + bias gives back f).
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "plumb/components/calibration_convert.hpp"
#include "test_samples.hpp"

namespace plumb::bridge_component {
using components::calibration_problem;
using components::to_model;
using components::to_topic;
namespace {

topics::CalibrationCoefficients distinct_coefficients() {
  topics::CalibrationCoefficients m;
  m.tool_id = "tool-7";
  m.calibration_id = "cal-2026-11-21";
  m.stamp_ns = 1'700'000'000'123'456'789;
  m.reference_temp_c = 24.5;
  m.temp_min_c = -10;
  m.temp_max_c = 150;
  m.thermometer = {0.5, 1.01, 1e-4, -2e-7};
  double v = 0.001;
  for (auto* t : {&m.accelerometer, &m.magnetometer}) {
    for (auto& x : t->bias) x = (v += 0.013);
    for (std::size_t i = 0; i < 9; ++i) t->sensitivity[i] = (i % 4 == 0 ? 1.0 : 0.0) + (v += 0.0007);
    for (auto& x : t->second_order) x = (v += 1e-5);
    for (auto& x : t->bias_temp) x = (v += 1e-4);
    for (auto& x : t->scale_temp) x = (v += 1e-6);
  }
  return m;
}

TEST(CalibrationConvert, TopicToModelAndBackIsExact) {
  const auto m = distinct_coefficients();
  const auto model = to_model(m);
  EXPECT_EQ(model.accelerometer.sensitivity(0, 1), m.accelerometer.sensitivity[1]);  // row-major
  EXPECT_EQ(model.magnetometer.sensitivity(2, 0), m.magnetometer.sensitivity[6]);
  auto back = to_topic(model);
  // The model keeps the time as double seconds: about 2.4e-7 s resolution at 1.7e9 s.
  EXPECT_NEAR(static_cast<double>(back.stamp_ns - m.stamp_ns), 0.0, 1000.0);
  back.stamp_ns = m.stamp_ns;
  EXPECT_EQ(back, m);
}

TEST(CalibrationApply, InvertsTheLinearSensorModelAtTheReferenceTemperature) {
  // Raw outputs of a sensor with bias and cross-axis sensitivity: u = S^-1 f + bias. With no
  // second-order or temperature terms the calibration must return f to rounding.
  CalibrationModel model;
  model.calibration_id = "linear";
  model.accelerometer.bias = {0.05, -0.03, 0.02};
  model.accelerometer.sensitivity << 1.01, 0.002, -0.001, 0.003, 0.99, 0.004, -0.002, 0.001, 1.02;
  model.magnetometer.bias = {1.5, -2.0, 0.7};
  model.magnetometer.sensitivity << 0.98, 0.01, 0, -0.01, 1.03, 0.02, 0, 0.005, 1.0;
  EXPECT_TRUE(calibration_problem(model).empty());
  Sample truth = bridge::test::make_sample(3);
  truth.flags &= ~flags::kHasTemperature;
  Sample raw = truth;
  raw.f = model.accelerometer.sensitivity.inverse() * truth.f + model.accelerometer.bias;
  raw.b = model.magnetometer.sensitivity.inverse() * truth.b + model.magnetometer.bias;
  model.apply(raw);
  EXPECT_TRUE(raw.flags & flags::kCalibrated);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(raw.f[i], truth.f[i], 1e-12 * truth.f.norm());
    EXPECT_NEAR(raw.b[i], truth.b[i], 1e-12 * truth.b.norm());
  }
}

TEST(CalibrationApply, TemperatureOutsideTheCalibratedRangeIsFlagged) {
  CalibrationModel model;
  model.temp_min_c = 0;
  model.temp_max_c = 100;
  Sample s = bridge::test::make_sample(0);
  s.temp_c = 120;
  model.apply(s);
  EXPECT_TRUE(s.flags & flags::kTemperatureOutOfRange);
}

TEST(CalibrationProblem, UnusableCoefficientsAreNamed) {
  CalibrationModel model;
  model.accelerometer.bias.x() = std::nan("");
  EXPECT_NE(calibration_problem(model).find("accelerometer"), std::string::npos);
  model = CalibrationModel{};
  model.magnetometer.sensitivity.row(2).setZero();
  EXPECT_NE(calibration_problem(model).find("singular"), std::string::npos);
}

}  // namespace
}  // namespace plumb::bridge_component
