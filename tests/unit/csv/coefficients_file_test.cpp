// The coefficients file: exact round trip in both versions, errors that name the line, units lines.
#include <random>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "plumb/csv/coefficients_file.hpp"

namespace plumb::csv {
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
  EXPECT_TRUE(a.bias_temp2 == b.bias_temp2);
  EXPECT_TRUE(a.bias_temp3 == b.bias_temp3);
  EXPECT_TRUE(a.sensor_scale_temp1 == b.sensor_scale_temp1);
  EXPECT_TRUE(a.sensor_scale_temp2 == b.sensor_scale_temp2);
  EXPECT_TRUE(a.sensor_scale_temp3 == b.sensor_scale_temp3);
}

// Version 2: the sensors' own temperature terms; odd seeds have them, even seeds are version 1.
CalibrationModel random_model_v2(std::uint64_t seed) {
  CalibrationModel m = random_model(seed);
  if (seed % 2) {
    m.accelerometer.bias_temp2 = 1e-6 * Eigen::Vector3d::Random();
    m.accelerometer.bias_temp3 = 1e-9 * Eigen::Vector3d::Random();
    m.accelerometer.sensor_scale_temp1 = 1e-5 * Eigen::Vector3d::Random();
    m.accelerometer.sensor_scale_temp2 = 1e-8 * Eigen::Vector3d::Random();
    m.accelerometer.sensor_scale_temp3 = 1e-11 * Eigen::Vector3d::Random();
  }
  return m;
}

TEST(CalibrationModelFile, VersionTwoRoundTripIsExactAndVersionOneStaysVersionOne) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const CalibrationModel m = random_model_v2(seed);
    std::stringstream s;
    write_calibration(s, m);
    const std::string text = s.str();
    const bool v2 = seed % 2;
    EXPECT_NE(text.find(v2 ? "format plumb-calibration 2\n" : "format plumb-calibration 1\n"), std::string::npos);
    // A version-1 model writes no version-2 key: its file is what it always was.
    EXPECT_EQ(text.find("sensor_scale_temp") != std::string::npos, v2);
    const CalibrationModel r = parse_calibration(s, "memory");
    expect_identical(r.accelerometer, m.accelerometer);
    expect_identical(r.magnetometer, m.magnetometer);
  }
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
  EXPECT_NE(parse_error("format plumb-calibration 3\n").find("version 3 is not supported"), std::string::npos);
  // Version-2 terms mean nothing in a file that says version 1, wherever the format line is.
  EXPECT_EQ(parse_error("accel.bias_temp2 1 2 3\nformat plumb-calibration 1\n"),
            "coeffs.txt:1: 'accel.bias_temp2' is a version-2 term but the file says 'format plumb-calibration 1'");
  EXPECT_NE(parse_error("temp_range_c 50 10\n").find("min < max"), std::string::npos);
  EXPECT_NE(parse_error("# nothing\n\n").find("no calibration coefficients"), std::string::npos);
  EXPECT_EQ(parse_error("accel.bias +1 -2e-3 3 # trailing comment\n"), "");
  EXPECT_THROW(read_calibration_file("/nonexistent/coeffs.txt"), std::runtime_error);
}

// The units of the package the coefficients were made for (docs/calibration.md "Binding").
TEST(CalibrationModelFile, UnitsLinesRoundTripAndVersionOneFilesLoadWithoutThem) {
  CalibrationModel m;
  m.tool_id = "T1";
  m.accel_units = "V";
  m.mag_units = "counts";
  std::stringstream file;
  write_calibration(file, m);
  EXPECT_NE(file.str().find("accel_units V\n"), std::string::npos) << file.str();
  const auto back = parse_calibration(file, "units.txt");
  EXPECT_EQ(back.accel_units, "V");
  EXPECT_EQ(back.mag_units, "counts");

  std::istringstream v1("format plumb-calibration 1\ntool_id T1\naccel.bias 0 0 0\n");
  const auto old = parse_calibration(v1, "v1.txt");
  EXPECT_EQ(old.accel_units, "");  // not stated: only the bridge's |G| check can tell
  EXPECT_EQ(old.mag_units, "");

  std::istringstream bad("accel_units metres per second\n");
  try {
    parse_calibration(bad, "bad.txt");
    FAIL() << "two words accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.txt:1: 'accel_units' needs one word"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plumb::csv
