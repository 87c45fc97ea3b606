// Station averaging waits for the settling transient and refuses a station that never settles.
#include <gtest/gtest.h>

#include "plumb/calibration/types.hpp"
#include "sim_support.hpp"

namespace plumb {
namespace {

TEST(StationAverage, WaitsForTheTransientAndAveragesToTheTruth) {
  const auto pkg = sim::SensorPackage::typical(sim::AccelOutput::Voltage, 3);
  sim::Rig rig;
  auto plans = sim::six_position_plan(30);
  const auto rec = sim::record(pkg, rig, plans);
  const auto stations = test::stations_of(rec);
  for (std::size_t i = 1; i < stations.size(); ++i) {
    const auto avg = calibration::average_station(rec.samples, stations[i]);
    // A move of ~2 g in raw units decays with tau = 1.5 s: it is below the noise of one reading
    // after a few tau, not before one tau.
    EXPECT_GT(avg.settled_after_s, pkg.settle_tau_s) << stations[i].name;
    EXPECT_LT(avg.settled_after_s, 15 * pkg.settle_tau_s) << stations[i].name;
    const Eigen::Vector3d truth = pkg.raw_accel(rec.stations[i].true_f, 25);
    for (int k = 0; k < 3; ++k) EXPECT_LT(std::abs(avg.accel[k] - truth[k]), 4 * avg.accel_se[k]) << stations[i].name;
  }
}

TEST(StationAverage, StationThatNeverSettlesIsAnErrorNamingIt) {
  const auto pkg = sim::SensorPackage::typical(sim::AccelOutput::Voltage, 3);
  auto plans = sim::six_position_plan(30);
  plans[2].settle_tau_s = 1000;  // drifts for the whole station
  const auto rec = sim::record(pkg, sim::Rig{}, plans);
  const auto stations = test::stations_of(rec);
  try {
    calibration::average_stations(rec.samples, stations);
    FAIL() << "no error";
  } catch (const calibration::CalibrationError& e) {
    EXPECT_NE(std::string(e.what()).find("station '" + plans[2].name + "': never settled"), std::string::npos) << e.what();
  }
  const auto out = calibration::six_position(rec.samples, stations);
  EXPECT_FALSE(out.ok());
  EXPECT_NE(out.error.find(plans[2].name), std::string::npos);
}

TEST(StationAverage, TooFewSamplesIsAnError) {
  const auto pkg = sim::SensorPackage::typical(sim::AccelOutput::Voltage, 3);
  const auto rec = sim::record(pkg, sim::Rig{}, sim::six_position_plan(2));
  const auto stations = test::stations_of(rec);
  EXPECT_THROW(calibration::average_station(rec.samples, stations[0]), calibration::CalibrationError);
  calibration::Station empty = stations[0];
  empty.start_s = 1e6;
  empty.end_s = 1e6 + 10;
  EXPECT_THROW(calibration::average_station(rec.samples, empty), calibration::CalibrationError);
}

}  // namespace
}  // namespace plumb
