// docs/methods.md section 2: 24 positions at several temperatures, thermometer non-linear above 175 degC.
#include <gtest/gtest.h>

#include "sim_support.hpp"

namespace plumb {
namespace {

const std::vector<double> kTemperaturesC = {25, 75, 125, 175, 200, 225};

struct Calibrated {
  sim::SensorPackage pkg;
  calibration::Outcome out;
};

Calibrated calibrate(sim::AccelOutput output, std::uint64_t seed) {
  Calibrated c{sim::SensorPackage::typical(output, seed), {}};
  sim::Rig rig;
  rig.seed = seed;
  rig.table_tilt_x_deg = 0.03;  // averaged out by the four rotations
  rig.table_tilt_y_deg = -0.02;
  const auto rec = sim::record(c.pkg, rig, sim::twenty_four_position_plan(kTemperaturesC, 40));
  calibration::TwentyFourOptions opt;
  opt.nominal = c.pkg.nominal;
  c.out = calibration::twenty_four_position(rec.samples, test::stations_of(rec), opt);
  return c;
}

class TwentyFour : public ::testing::TestWithParam<sim::AccelOutput> {};

TEST_P(TwentyFour, RecoversEveryParameterWithinThreeSigma) {
  const auto c = calibrate(GetParam(), 31);
  ASSERT_TRUE(c.out.ok()) << c.out.error;
  test::print_outcome_warnings(c.out);
  const auto& r = *c.out.result;
  const auto& truth = c.pkg.truth.accelerometer;
  int n = test::expect_triad_within_sd(r, "accel.", truth);
  const char* const ax = "xyz";
  for (int i = 0; i < 3; ++i) {
    n += test::expect_within_sd(r, std::string("accel.bias_temp.") + ax[i], truth.bias_temp[i]);
    // The simulator's scale drift is on each sensor's output (model version 2).
    n += test::expect_within_sd(r, std::string("accel.sensor_scale_temp1.") + ax[i], truth.sensor_scale_temp1[i]);
  }
  for (int k = 0; k < 4; ++k)
    n += test::expect_within_sd(r, "thermometer.c" + std::to_string(k), c.pkg.truth.thermometer[static_cast<std::size_t>(k)]);
  EXPECT_EQ(n, 25);
  EXPECT_EQ(r.model.temp_min_c < 26 && r.model.temp_max_c > 224, true);
}

TEST_P(TwentyFour, InclinationWithin002DegAcrossTheCalibratedRange) {
  const auto c = calibrate(GetParam(), 32);
  ASSERT_TRUE(c.out.ok()) << c.out.error;
  std::vector<double> temps;
  for (double T = 25; T <= 225; T += 10) temps.push_back(T);
  const double after = test::max_inclination_error(c.pkg, c.out.result->model, temps);
  const double before = test::max_inclination_error(c.pkg, c.pkg.nominal, temps);
  std::printf("24-position (%s), 25..225 degC: max inclination error before %.4f deg, after %.5f deg\n",
              GetParam() == sim::AccelOutput::Voltage ? "voltage" : "pulse rate", before, after);
  EXPECT_LT(after, 0.02);
  EXPECT_GT(before, 0.02);
  // Without the thermometer correction and temperature terms the hot end is worse than after.
  CalibrationModel no_temp = c.out.result->model;
  no_temp.accelerometer.bias_temp.setZero();
  no_temp.accelerometer.scale_temp.setZero();
  no_temp.accelerometer.sensor_scale_temp1.setZero();
  const double no_temp_err = test::max_inclination_error(c.pkg, no_temp, temps);
  std::printf("  same coefficients without the temperature terms: %.4f deg\n", no_temp_err);
  EXPECT_GT(no_temp_err, after);
}

INSTANTIATE_TEST_SUITE_P(Outputs, TwentyFour, ::testing::Values(sim::AccelOutput::Voltage, sim::AccelOutput::PulseRate));

class TwentyFourBadInput : public ::testing::Test {
 protected:
  sim::SensorPackage pkg = sim::SensorPackage::typical(sim::AccelOutput::Voltage, 41);
  std::vector<sim::StationPlan> plans = sim::twenty_four_position_plan({25, 125}, 30);
  calibration::Outcome run() {
    const auto rec = sim::record(pkg, sim::Rig{}, plans);
    return calibration::twenty_four_position(rec.samples, test::stations_of(rec));
  }
};

TEST_F(TwentyFourBadInput, MissingRotationIsNamed) {
  plans.erase(plans.begin() + 30);  // second run, face -x (4..7), rotation 180
  const auto o = run();
  EXPECT_FALSE(o.ok());
  EXPECT_NE(o.error.find("run '125C': position -x@180 is missing"), std::string::npos) << o.error;
}

TEST_F(TwentyFourBadInput, RepeatedPositionIsNamed) {
  plans[5] = plans[4];
  plans[5].name = "dup";
  const auto o = run();
  EXPECT_FALSE(o.ok());
  EXPECT_NE(o.error.find("position -x@0 is repeated"), std::string::npos) << o.error;
}

TEST_F(TwentyFourBadInput, WrongOrientationIsNamed) {
  sim::axis_up_attitude(1, -1, plans[9].inclination_deg, plans[9].toolface_deg);  // "+y@90" placed at -y
  const auto o = run();
  EXPECT_FALSE(o.ok());
  EXPECT_NE(o.error.find("station '" + plans[9].name + "'"), std::string::npos) << o.error;
  EXPECT_NE(o.error.find("as if at -y"), std::string::npos) << o.error;
}

TEST_F(TwentyFourBadInput, UnstableTemperatureIsAWarningNamingTheStation) {
  plans[7].temperature_c = 31;  // chamber not at its set point yet
  const auto o = run();
  ASSERT_TRUE(o.ok()) << o.error;
  bool named = false;
  for (const auto& w : o.warnings) named |= w.find("station '" + plans[7].name + "'") != std::string::npos;
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace plumb
