// The coefficients model and its file: exact round trip, exact inverse of the simulator, errors
// that name the line.
#include <cmath>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "plumb/core/calibration_model.hpp"
#include "plumb/sim/turntable.hpp"

namespace plumb {
namespace {

CalibrationModel random_model(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  CalibrationModel m;
  m.tool_id = "tool 42";
  m.calibration_id = "cal-2026-11-21";
  m.stamp_s = 1.7e9 + n(rng);
  m.reference_temp_c = 25 + n(rng);
  m.temp_min_c = -10 + n(rng);
  m.temp_max_c = 180 + n(rng);
  for (auto& c : m.thermometer) c = n(rng) * 1e-3;
  for (TriadModel* t : {&m.accelerometer, &m.magnetometer}) {
    t->bias = Eigen::Vector3d::Random();
    t->sensitivity = Eigen::Matrix3d::Random();
    t->second_order = 1e-5 * Eigen::Vector3d::Random();
    t->bias_temp = 1e-4 * Eigen::Vector3d::Random();
    t->scale_temp = 1e-5 * Eigen::Vector3d::Random();
  }
  m.accelerometer.bias[0] = 1.0 / 3.0;  // needs all 17 digits
  m.magnetometer.bias[1] = -0.0;
  return m;
}

void expect_identical(const TriadModel& a, const TriadModel& b) {
  EXPECT_TRUE(a.bias == b.bias);
  EXPECT_TRUE(a.sensitivity == b.sensitivity);
  EXPECT_TRUE(a.second_order == b.second_order);
  EXPECT_TRUE(a.bias_temp == b.bias_temp);
  EXPECT_TRUE(a.scale_temp == b.scale_temp);
}

TEST(CalibrationModelFile, RoundTripIsExact) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const CalibrationModel m = random_model(seed);
    std::stringstream s;
    write_calibration(s, m);
    const CalibrationModel r = parse_calibration(s, "memory");
    EXPECT_EQ(r.tool_id, m.tool_id);
    EXPECT_EQ(r.calibration_id, m.calibration_id);
    EXPECT_EQ(r.stamp_s, m.stamp_s);
    EXPECT_EQ(r.reference_temp_c, m.reference_temp_c);
    EXPECT_EQ(r.temp_min_c, m.temp_min_c);
    EXPECT_EQ(r.temp_max_c, m.temp_max_c);
    EXPECT_EQ(r.thermometer, m.thermometer);
    expect_identical(r.accelerometer, m.accelerometer);
    expect_identical(r.magnetometer, m.magnetometer);
  }
}

std::string parse_error(const std::string& text) {
  std::istringstream in(text);
  try {
    parse_calibration(in, "coeffs.txt");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(CalibrationModelFile, BadLinesAreNamed) {
  EXPECT_EQ(parse_error("# c\naccel.bias 1 2\n"), "coeffs.txt:2: 'accel.bias' needs 3 values, got 2");
  EXPECT_NE(parse_error("format plumb-calibration 1\nacel.bias 1 2 3\n").find("coeffs.txt:2: unknown key 'acel.bias'"),
            std::string::npos);
  EXPECT_NE(parse_error("accel.bias 1 2 x\n").find("coeffs.txt:1:"), std::string::npos);
  EXPECT_NE(parse_error("accel.bias 1 2 nan\n").find("not finite"), std::string::npos);
  EXPECT_NE(parse_error("accel.bias 1 2 3\naccel.bias 1 2 3\n").find("given twice"), std::string::npos);
  EXPECT_NE(parse_error("format plumb-calibration 2\n").find("version 2"), std::string::npos);
  EXPECT_NE(parse_error("temp_range_c 50 10\n").find("min < max"), std::string::npos);
  EXPECT_NE(parse_error("# nothing\n\n").find("no calibration coefficients"), std::string::npos);
  EXPECT_EQ(parse_error("accel.bias +1 -2e-3 3 # trailing comment\n"), "");
  EXPECT_THROW(read_calibration_file("/nonexistent/coeffs.txt"), std::runtime_error);
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
