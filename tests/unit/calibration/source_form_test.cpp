// The procedures on packages that plumb's own model did not write (source_form_package.hpp):
// accuracy over orientations and temperatures that are not the stations, disturbed stations,
// counted outputs, and the bad input the sensors' own temperature model brings.
#include <gtest/gtest.h>

#include "plumb/calibration/report.hpp"
#include "source_form_support.hpp"

namespace plumb {
namespace {

using namespace test::source;

const std::vector<double> kOvenTemperaturesC = {25, 65, 105, 145, 185, 225};

Rig tilted_rig() {
  Rig rig;
  rig.tilt_x_deg = 0.03;   // a table top a few hundredths of a degree off level
  rig.tilt_y_deg = -0.02;
  return rig;
}

TEST(SourceForm, SixPositionVoltageAndPulsesWithin00005Deg) {
  for (bool pulses : {false, true}) {
    std::mt19937_64 rng(pulses ? 702 : 701);
    const Package pkg = Package::random(rng, pulses, 2);
    const Trial t = six_position_trial(pkg, Rig{}, six_positions(60), pulses ? 72 : 71);
    ASSERT_TRUE(t.outcome.ok()) << t.outcome.error;
    std::printf("6-position (%s): worst inclination error before %.3f deg, after %.6f deg, predicted %.6f deg\n",
                pulses ? "pulses" : "volts", t.before_deg, t.after_deg, t.outcome.result->predicted.inclination_deg);
    EXPECT_GT(t.before_deg, 0.05);   // the errors the calibration removes are real
    expect_honest(t, pulses ? "pulses" : "volts", 0.0005);
  }
}

TEST(SourceForm, TwentyFourPositionWithQuadraticDriftWithin00005DegOverTheRange) {
  std::mt19937_64 rng(703);
  const Package pkg = Package::random(rng, false, 2);
  const Trial t = twenty_four_trial(pkg, tilted_rig(), kOvenTemperaturesC, 30, 73);
  ASSERT_TRUE(t.outcome.ok()) << t.outcome.error;
  const auto& r = *t.outcome.result;
  std::printf("24-position (volts, order chosen %s): worst inclination error before %.3f deg, after %.6f deg, "
              "predicted %.6f deg\n%s\n",
              r.model.accelerometer.bias_temp2.isZero(0) ? "1" : (r.model.accelerometer.bias_temp3.isZero(0) ? "2" : "3"),
              t.before_deg, t.after_deg, r.predicted.inclination_deg, r.summary.c_str());
  EXPECT_GT(t.before_deg, 0.05);
  expect_honest(t, "24pos", 0.0005);
  // A drift of order 2 needs order 2: the criterion must not stop at 1.
  EXPECT_FALSE(r.model.accelerometer.bias_temp2.isZero(0));
  // The table's tilt shows in the stations' orientations, not in what the sensors' errors leave.
  ASSERT_TRUE(r.split.valid);
  EXPECT_GT(r.split.orientation_deg, 0.02);
  EXPECT_LT(r.split.sensor_deg, 0.002);
  // The report says so, and states the predicted error in use.
  const std::string report = calibration::format_report(t.outcome, "24pos");
  EXPECT_NE(report.find("predicted error of this calibration in use"), std::string::npos);
  EXPECT_NE(report.find("of which the sensors' errors"), std::string::npos);
  EXPECT_NE(report.find("table top tilt"), std::string::npos);
  std::printf("%s\n", report.substr(0, report.find("\nparameters")).c_str());
}

TEST(SourceForm, TwentyFourPositionPulsesWithLinearDriftChoosesOrderOne) {
  // A drift linear in temperature: the criterion keeps order 1 (the further coefficients explain
  // only noise), and counted outputs reach the same accuracy.
  std::mt19937_64 rng(704);
  const Package pkg = Package::random(rng, true, 1);
  const Trial t = twenty_four_trial(pkg, Rig{}, {25, 125, 225}, 30, 74);
  ASSERT_TRUE(t.outcome.ok()) << t.outcome.error;
  std::printf("24-position (pulses, linear drift): before %.3f deg, after %.6f deg\n", t.before_deg, t.after_deg);
  EXPECT_TRUE(t.outcome.result->model.accelerometer.bias_temp2.isZero(0));
  expect_honest(t, "24pos pulses", 0.0005);
}

TEST(SourceForm, TooFewTemperaturesForTheChosenOrderIsOneLineAndNoCoefficients) {
  std::mt19937_64 rng(705);
  const Package pkg = Package::random(rng, false, 1);
  const Trial t = twenty_four_trial(pkg, Rig{}, {25, 125}, 20, 75, 2);
  EXPECT_FALSE(t.outcome.ok());
  EXPECT_NE(t.outcome.error.find("temperature order 2 needs at least 3 temperature runs, got 2"), std::string::npos)
      << t.outcome.error;
  EXPECT_EQ(t.outcome.error.find('\n'), std::string::npos);
}

TEST(SourceForm, AMisplacedTwentyFourPositionStationIsDroppedWithALine) {
  std::mt19937_64 rng(707);
  const Package pkg = Package::random(rng, false, 1);
  auto positions = twenty_four_positions({25, 125, 225}, 30);
  // Station 125C/+y@180 sits 1 deg off (the tool not seated): the whole station, still. (Its
  // reading along the up axis moves by g (1 - cos 1 deg), 24 standard errors: at 0.5 deg, 6, the
  // limit itself, and which side of it depended on the compiler's rounding of the simulation.)
  positions[24 + 2 * 4 + 2].disturbance = [](double) {
    return Eigen::AngleAxisd(1.0 * kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix();
  };
  const Recording rec = record(pkg, tilted_rig(), positions, 87);
  calibration::TwentyFourOptions opt;
  opt.nominal = nominal_model(pkg);
  Trial t;
  t.outcome = calibration::twenty_four_position(rec.samples, rec.stations, opt);
  ASSERT_TRUE(t.outcome.ok()) << t.outcome.error;
  judge(t, pkg, rng, 25, 225);
  const auto& dropped = t.outcome.result->dropped;
  ASSERT_EQ(dropped.size(), 1u);
  EXPECT_NE(dropped.front().find("station '125C/+y@180' left out"), std::string::npos) << dropped.front();
  std::printf("misplaced 24-position station dropped: true error %.6f deg\n", t.after_deg);
  expect_honest(t, "misplaced", 0.0005);
}

TEST(SourceForm, AStationSlightlyOffThatCannotBeToldIsRefused) {
  std::mt19937_64 rng(708);
  const Package pkg = Package::random(rng, false, 1);
  auto positions = twenty_four_positions({25, 125}, 30);
  // 0.02 deg off: its horizontal readings break the rotations' sinusoid, its up-axis reading
  // (g (1 - cos 0.02 deg) = 6e-7 m/s^2) does not tell it from the others.
  positions[1].disturbance = [](double) {
    return Eigen::AngleAxisd(0.02 * kDeg, Eigen::Vector3d::UnitY()).toRotationMatrix();
  };
  const Recording rec = record(pkg, Rig{}, positions, 88);
  const auto out = calibration::twenty_four_position(rec.samples, rec.stations);
  EXPECT_FALSE(out.ok());
  EXPECT_NE(out.error.find("run '25C': face +x: the four rotations"), std::string::npos) << out.error;
  EXPECT_NE(out.error.find("'25C/+x@90'"), std::string::npos) << out.error;
}

TEST(SourceForm, PredictedErrorAboveTheToleranceWritesNoCoefficients) {
  std::mt19937_64 rng(709);
  Package pkg = Package::random(rng, false, 1);
  pkg.noise = 0.05;   // a noisy package on short stations
  const Recording rec = record(pkg, Rig{}, six_positions(10), 89);
  calibration::CommonOptions opt;
  const auto out = calibration::six_position(rec.samples, rec.stations, opt);
  EXPECT_FALSE(out.ok());
  EXPECT_NE(out.error.find("exceeds the tolerance 0.005 deg (--max-error-deg)"), std::string::npos) << out.error;
  opt.max_error_deg = 1;   // the same data with a looser tolerance: coefficients and the prediction
  const auto loose = calibration::six_position(rec.samples, rec.stations, opt);
  ASSERT_TRUE(loose.ok()) << loose.error;
  EXPECT_GT(loose.result->predicted.inclination_deg, 0.005);
}

// --- Disturbed stations (6-position, volts) ---------------------------------------------------

class Disturbed : public ::testing::Test {
 protected:
  std::mt19937_64 rng{706};
  Package pkg = Package::random(rng, false, 1);
  std::vector<Position> positions = six_positions(60);
  Rig rig;

  Trial run(std::uint64_t seed = 76) { return six_position_trial(pkg, rig, positions, seed); }
  // A rotation of `deg` about the tool's x or y axis.
  static Eigen::Matrix3d tilt(double deg, int axis) {
    return Eigen::AngleAxisd(deg * kDeg, axis == 0 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY())
        .toRotationMatrix();
  }
  void expect_refused_naming(const Trial& t, const std::string& station, const std::string& what) {
    EXPECT_FALSE(t.outcome.ok());
    EXPECT_FALSE(t.outcome.result.has_value());
    EXPECT_NE(t.outcome.error.find("station '" + station + "'"), std::string::npos) << t.outcome.error;
    EXPECT_NE(t.outcome.error.find(what), std::string::npos) << t.outcome.error;
    std::printf("refused: %s\n", t.outcome.error.c_str());
  }
};

TEST_F(Disturbed, UndisturbedBaseline) {
  const Trial t = run();
  ASSERT_TRUE(t.outcome.ok()) << t.outcome.error;
  expect_honest(t, "baseline", 0.0005);
}

TEST_F(Disturbed, WindowRunningIntoTheMoveIsCutToTheStillPart) {
  // The window's end is 5 s into the 10 s move to the next position.
  Recording rec = record(pkg, rig, positions, 77);
  rec.stations[2].end_s += 5;
  calibration::CommonOptions opt;
  opt.nominal = nominal_model(pkg);
  Trial t;
  t.outcome = calibration::six_position(rec.samples, rec.stations, opt);
  judge(t, pkg, rng, 25, 25);
  ASSERT_TRUE(t.outcome.ok()) << t.outcome.error;
  bool noted = false;
  for (const auto& w : t.outcome.warnings) noted |= w.find("station 'p+y': motion at t =") != std::string::npos;
  EXPECT_TRUE(noted);
  std::printf("window 5 s into the move: handled, true error %.6f deg\n", t.after_deg);
  expect_honest(t, "into the move", 0.005);
}

TEST_F(Disturbed, WindowRunning90SIntoTheMoveIsRefused) {
  // The last station's window runs 90 s on while the tool is taken off the table and left there.
  rig.rest_s = 100;
  Recording rec = record(pkg, rig, positions, 78);
  rec.stations.back().end_s += 90;
  Trial t;
  t.outcome = calibration::six_position(rec.samples, rec.stations);
  expect_refused_naming(t, "p-z", "the tool moved at t = ");
}

TEST_F(Disturbed, WindowRunningIntoTheNextStationIsAnOverlap) {
  Recording rec = record(pkg, rig, positions, 79);
  rec.stations[1].end_s += 90;
  Trial t;
  t.outcome = calibration::six_position(rec.samples, rec.stations);
  EXPECT_FALSE(t.outcome.ok());
  EXPECT_NE(t.outcome.error.find("stations 'p-x'"), std::string::npos) << t.outcome.error;
  EXPECT_NE(t.outcome.error.find("overlap"), std::string::npos) << t.outcome.error;
}

TEST_F(Disturbed, KnockedHalfADegreeMidStationIsRefusedWithItsTime) {
  positions[3].disturbance = [](double s) { return s > 30 ? tilt(0.5, 0) : Eigen::Matrix3d::Identity(); };
  expect_refused_naming(run(), "p-y", "the tool moved at t = ");
}

TEST_F(Disturbed, LiftedThreeDegreesForFiveSecondsAndPutBackIsHandled) {
  positions[4].disturbance = [](double s) {
    // Lifted over 0.5 s, held 5 s, put back over 0.5 s, from 25 s into the station.
    const double x = s < 25 ? 0 : s < 25.5 ? (s - 25) / 0.5 : s < 30.5 ? 1 : s < 31 ? (31 - s) / 0.5 : 0;
    return tilt(3 * x, 1);
  };
  const Trial t = run();
  ASSERT_TRUE(t.outcome.ok()) << t.outcome.error;
  bool noted = false;
  for (const auto& w : t.outcome.warnings) noted |= w.find("station 'p+z': motion at t =") != std::string::npos;
  EXPECT_TRUE(noted);
  std::printf("lifted and put back: handled, true error %.6f deg\n", t.after_deg);
  expect_honest(t, "lifted", 0.005);
}

TEST_F(Disturbed, LiftedAndPutBackWithCountedOutputsIsHandled) {
  pkg = Package::random(rng, true, 1);
  positions[2].disturbance = [](double s) { return s > 20 && s < 25 ? tilt(3, 0) : Eigen::Matrix3d::Identity(); };
  const Trial t = run(80);
  ASSERT_TRUE(t.outcome.ok()) << t.outcome.error;
  std::printf("lifted and put back (pulses): handled, true error %.6f deg\n", t.after_deg);
  expect_honest(t, "lifted, pulses", 0.005);
}

TEST_F(Disturbed, KnockedWithCountedOutputsIsRefused) {
  pkg = Package::random(rng, true, 1);
  positions[0].disturbance = [](double s) { return s > 40 ? tilt(0.5, 1) : Eigen::Matrix3d::Identity(); };
  expect_refused_naming(run(81), "p+x", "the tool moved at t = ");
}

TEST_F(Disturbed, SteadySlowTurnIsRefused) {
  positions[1].disturbance = [](double s) { return tilt(0.01 * s, 1); };   // 0.01 deg/s for the whole station
  const Trial t = run();
  EXPECT_FALSE(t.outcome.ok());
  EXPECT_NE(t.outcome.error.find("station 'p-x'"), std::string::npos) << t.outcome.error;
  std::printf("slow turn: %s\n", t.outcome.error.c_str());
}

}  // namespace
}  // namespace plumb
