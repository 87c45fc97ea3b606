// Static positions in unknown orientations, and the bad inputs of the least-squares fit.
#include <gtest/gtest.h>

#include "plumb/calibration/fit.hpp"
#include "sim_support.hpp"

namespace plumb {
namespace {

sim::SensorPackage linear_package(std::uint64_t seed) {
  auto pkg = sim::SensorPackage::typical(sim::AccelOutput::Voltage, seed, false);
  pkg.truth.accelerometer.second_order.setZero();  // the fit's model is linear
  return pkg;
}

TEST(LeastSquares, RecoversBiasAndTriangularSensitivityWithinThreeSigma) {
  const auto pkg = linear_package(51);
  sim::Rig rig;
  rig.seed = 51;
  const auto rec = sim::record(pkg, rig, sim::random_static_plan(24, 52, 30));
  calibration::LeastSquaresOptions opt;
  const auto out = calibration::least_squares(rec.samples, test::stations_of(rec), opt);
  ASSERT_TRUE(out.ok()) << out.error;
  test::print_outcome_warnings(out);
  const auto& r = *out.result;
  // |S v| = |L v| with L lower triangular and L^T L = S^T S: the identifiable part of the truth.
  const Eigen::Matrix3d& S = pkg.truth.accelerometer.sensitivity;
  const Eigen::Matrix3d L = calibration::lower_factor(S.transpose() * S);
  const char* const ax = "xyz";
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    n += test::expect_within_sd(r, std::string("accel.bias.") + ax[i], pkg.truth.accelerometer.bias[i]);
    for (int j = 0; j <= i; ++j) n += test::expect_within_sd(r, std::string("accel.sensitivity.") + ax[i] + ax[j], L(i, j));
  }
  EXPECT_EQ(n, 9);
  std::printf("least squares, 24 positions: |f| residual rms %.2e m/s^2\n", r.residual_rms);
  // Inclination needs the tool frame; in the accelerometer frame the truth is L, so compare with
  // a truth model whose S is L.
  sim::SensorPackage framed = pkg;
  framed.truth.accelerometer.sensitivity = L;
  // Same raw outputs, physical vectors rotated into the accelerometer frame: f' = L S^-1 f.
  const Eigen::Matrix3d R = L * S.inverse();
  double worst = 0;
  for (double inc = 0; inc <= 180; inc += 7.5)
    for (double tf = 0; tf < 360; tf += 30) {
      const Eigen::Vector3d f = -gravity_tool(inc * kDeg, tf * kDeg, 9.80665);
      const Eigen::Vector3d raw = pkg.raw_accel(R.transpose() * f, 25);  // reads f in the accelerometer frame
      const Eigen::Vector3d est = r.model.accelerometer.apply(raw, 0);
      worst = std::max(worst, std::abs(std::atan2(std::hypot(est.x(), est.y()), -est.z()) / kDeg - inc));
    }
  std::printf("least squares: max inclination error in the accelerometer frame %.5f deg\n", worst);
  EXPECT_LT(worst, 0.02);
}

TEST(LeastSquares, TooFewStationsIsAnErrorNamingTheCount) {
  const auto pkg = linear_package(53);
  const auto rec = sim::record(pkg, sim::Rig{}, sim::random_static_plan(8, 54, 30));
  const auto out = calibration::least_squares(rec.samples, test::stations_of(rec));
  EXPECT_FALSE(out.ok());
  EXPECT_NE(out.error.find("at least 12"), std::string::npos) << out.error;
  EXPECT_NE(out.error.find("got 8"), std::string::npos) << out.error;
}

TEST(LeastSquares, PositionsTurnedAboutOneAxisOnlyAreRejected) {
  const auto pkg = linear_package(55);
  auto plans = sim::random_static_plan(16, 56, 30);
  for (auto& p : plans) p.inclination_deg = 90;  // z always horizontal: z bias and scale undetermined
  const auto rec = sim::record(pkg, sim::Rig{}, plans);
  const auto out = calibration::least_squares(rec.samples, test::stations_of(rec));
  EXPECT_FALSE(out.ok());
  EXPECT_NE(out.error.find("not spread over all directions"), std::string::npos) << out.error;
}

TEST(LeastSquares, TemperatureOutsideTheBaseRangeIsAWarningNamingTheStation) {
  const auto pkg = linear_package(57);
  auto plans = sim::random_static_plan(14, 58, 30);
  plans[4].temperature_c = 90;
  const auto rec = sim::record(pkg, sim::Rig{}, plans);
  calibration::LeastSquaresOptions opt;
  opt.base.temp_min_c = 0;
  opt.base.temp_max_c = 60;
  const auto out = calibration::least_squares(rec.samples, test::stations_of(rec), opt);
  ASSERT_TRUE(out.ok()) << out.error;
  bool named = false;
  for (const auto& w : out.warnings) named |= w.find("station 's5' is at 90") != std::string::npos;
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace plumb
