// Hard and soft iron with the constant-dip constraint.
#include <gtest/gtest.h>

#include "sim_support.hpp"

namespace plumb {
namespace {

TEST(Magnetometer, RecoversHardAndSoftIronAndDipWithinThreeSigma) {
  const auto pkg = sim::SensorPackage::typical(sim::AccelOutput::Voltage, 61, false);
  sim::Rig rig;
  rig.seed = 61;
  const auto rec = sim::record(pkg, rig, sim::random_static_plan(30, 62, 30));
  calibration::MagnetometerOptions opt;
  opt.base = pkg.truth;  // accelerometers already calibrated: their frame is the tool frame
  opt.base.magnetometer = TriadModel{};
  opt.total_field_ut = rig.total_b;
  const auto out = calibration::magnetometer(rec.samples, test::stations_of(rec), opt);
  ASSERT_TRUE(out.ok()) << out.error;
  test::print_outcome_warnings(out);
  const auto& r = *out.result;
  EXPECT_EQ(test::expect_triad_within_sd(r, "mag.", pkg.truth.magnetometer, false), 12);
  EXPECT_EQ(test::expect_within_sd(r, "mag.sin_dip", std::sin(rig.dip_deg * kDeg)), 1);
  // Field direction error after calibration, over orientations: azimuth-grade accuracy.
  double worst = 0, before = 0;
  for (double inc = 5; inc <= 175; inc += 10)
    for (double azi = 0; azi < 360; azi += 30) {
      const Eigen::Vector3d b = field_tool(inc * kDeg, azi * kDeg, 0.7, rig.total_b, rig.dip_deg * kDeg);
      const Eigen::Vector3d raw = pkg.raw_mag(b, 25);
      const Eigen::Vector3d est = r.model.magnetometer.apply(raw, 0);
      const Eigen::Vector3d nom = pkg.nominal.magnetometer.apply(raw, 0);
      worst = std::max(worst, std::acos(std::clamp(est.normalized().dot(b.normalized()), -1.0, 1.0)) / kDeg);
      before = std::max(before, std::acos(std::clamp(nom.normalized().dot(b.normalized()), -1.0, 1.0)) / kDeg);
    }
  std::printf("magnetometer: max field direction error before %.3f deg, after %.4f deg\n", before, worst);
  EXPECT_LT(worst, 0.05);
}

TEST(Magnetometer, TooFewStationsIsAnError) {
  const auto pkg = sim::SensorPackage::typical(sim::AccelOutput::Voltage, 63, false);
  const auto rec = sim::record(pkg, sim::Rig{}, sim::random_static_plan(6, 64, 30));
  calibration::MagnetometerOptions opt;
  opt.base = pkg.truth;
  const auto out = calibration::magnetometer(rec.samples, test::stations_of(rec), opt);
  EXPECT_FALSE(out.ok());
  EXPECT_NE(out.error.find("got 6"), std::string::npos) << out.error;
}

}  // namespace
}  // namespace plumb
