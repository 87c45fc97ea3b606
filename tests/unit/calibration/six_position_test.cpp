// docs/methods.md section 3 on simulated packages with known coefficients.
#include <gtest/gtest.h>

#include "plumb/calibration/triad_fit.hpp"
#include "sim_support.hpp"

namespace plumb {
namespace {

struct SixPositionCase {
  sim::AccelOutput output;
  std::uint64_t seed;
};

class SixPosition : public ::testing::TestWithParam<SixPositionCase> {};

TEST_P(SixPosition, RecoversEveryParameterWithinThreeSigmaAndInclinationWithin002Deg) {
  const auto pkg = sim::SensorPackage::typical(GetParam().output, GetParam().seed, false);
  sim::Rig rig;
  rig.seed = GetParam().seed;
  const auto rec = sim::record(pkg, rig, sim::six_position_plan(60));
  calibration::CommonOptions opt;
  opt.nominal = pkg.nominal;
  const auto out = calibration::six_position(rec.samples, test::stations_of(rec), opt);
  ASSERT_TRUE(out.ok()) << out.error;
  test::print_outcome_warnings(out);
  const auto& r = *out.result;
  EXPECT_EQ(test::expect_triad_within_sd(r, "accel.", pkg.truth.accelerometer), 15);

  // Predicted from the noise and the design: each bias is the mean of the two station sums where
  // its axis is horizontal, sd = sigma / (2 sqrt(N)) (voltage output: white noise only; the
  // counted pulses' quantisation makes the scatter-based sd an upper bound instead).
  if (GetParam().output == sim::AccelOutput::Voltage) {
    const Eigen::Matrix3d A = pkg.truth.accelerometer.sensitivity.inverse();
    const double n_used = 0.9 * 60 * rig.sample_rate_hz;  // most of each station is after settling
    const char* const ax = "xyz";
    for (int i = 0; i < 3; ++i) {
      const double predicted = pkg.accel_noise * A.row(i).norm() / (2 * std::sqrt(n_used));
      const auto* p = calibration::find_parameter(r, std::string("accel.bias.") + ax[i]);
      ASSERT_NE(p, nullptr);
      EXPECT_GT(p->sd, 0.8 * predicted);
      EXPECT_LT(p->sd, 1.25 * predicted);
    }
  }

  const double after = test::max_inclination_error(pkg, r.model, {20, 25, 30});
  const double before = test::max_inclination_error(pkg, pkg.nominal, {20, 25, 30});
  std::printf("6-position (%s): max inclination error before %.4f deg, after %.5f deg\n",
              GetParam().output == sim::AccelOutput::Voltage ? "voltage" : "pulse rate", before, after);
  EXPECT_LT(after, 0.02);
  EXPECT_GT(before, 0.02);  // the errors the calibration removes are real
}

INSTANTIATE_TEST_SUITE_P(Packages, SixPosition,
                         ::testing::Values(SixPositionCase{sim::AccelOutput::Voltage, 11},
                                           SixPositionCase{sim::AccelOutput::PulseRate, 12}));

class SixPositionBadInput : public ::testing::Test {
 protected:
  sim::SensorPackage pkg = sim::SensorPackage::typical(sim::AccelOutput::Voltage, 21);
  sim::Rig rig;
  std::vector<sim::StationPlan> plans = sim::six_position_plan(30);
  calibration::Outcome run() {
    const auto rec = sim::record(pkg, rig, plans);
    return calibration::six_position(rec.samples, test::stations_of(rec));
  }
  void expect_error(const calibration::Outcome& o, const std::string& part) {
    EXPECT_FALSE(o.ok());
    EXPECT_FALSE(o.result.has_value());  // no half results
    EXPECT_NE(o.error.find(part), std::string::npos) << o.error;
  }
};

TEST_F(SixPositionBadInput, MissingPosition) {
  plans.erase(plans.begin() + 3);  // -y
  expect_error(run(), "position -y is missing");
}

TEST_F(SixPositionBadInput, RepeatedPosition) {
  plans[3] = plans[2];
  plans[3].name = "again";
  expect_error(run(), "position +y is repeated: stations 'p+y' and 'again'");
}

TEST_F(SixPositionBadInput, ToolInTheWrongOrientationIsFoundAndNamed) {
  // Labelled +y but placed with z up.
  sim::axis_up_attitude(2, 1, plans[2].inclination_deg, plans[2].toolface_deg);
  expect_error(run(), "station 'p+y' (+y): the tool reads as if at +z");
}

TEST_F(SixPositionBadInput, ToolUpsideDownIsFoundAndNamed) {
  sim::axis_up_attitude(0, -1, plans[0].inclination_deg, plans[0].toolface_deg);
  expect_error(run(), "station 'p+x' (+x): the tool reads as if at -x");
}

TEST_F(SixPositionBadInput, StationWithoutOrientation) {
  plans[1].orientation = "any";
  expect_error(run(), "station 'p-x' has no orientation");
}

// The live procedure checks each station before recording it, with the offline rule: a station
// alone (no other to tell the offsets) is judged by its raw direction.
TEST(CheckOrientations, AStationAloneIsJudgedByItsRawDirection) {
  calibration::StationAverage s;
  s.station.name = "p+x";
  s.station.orientation = calibration::parse_orientation("+x");
  s.accel = Eigen::Vector3d(0.01, 0.02, -2.45);  // volts, z axis pointing down
  try {
    calibration::check_orientations({&s}, 10);
    FAIL() << "a station with z down was taken for +x";
  } catch (const calibration::CalibrationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("station 'p+x' (+x): the tool reads as if at -z"), std::string::npos) << what;
  }
  s.accel = Eigen::Vector3d(2.45, 0.01, 0.02);
  EXPECT_NO_THROW(calibration::check_orientations({&s}, 10));
}

}  // namespace
}  // namespace plumb
