// What clipped readings could hide (SensorRange): each clipped axis is an unknown of its own, so
// two axes clipped at once widen the attitude (or the velocity) about both, not about their
// diagonal alone; within an epoch an axis's excesses add up.
#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "plumb/strapdown/sensor_range.hpp"

namespace plumb::strapdown {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

NavigatorConfig ranges() {
  NavigatorConfig c;
  c.gyro_range = 2000 * kDeg;
  c.gyro_rate_max = 3000 * kDeg;
  c.accel_range = 16 * 9.80665;
  c.accel_shock_max = 50 * 9.80665;
  return c;
}

// The variance along direction u (NED) of a 3 x 3 noise.
double along(const Eigen::Matrix3d& m, const Eigen::Vector3d& u) { return u.normalized().dot(m * u.normalized()); }

TEST(SensorRange, TwoGyrosClippedAtOnceAreTwoUnknowns) {
  SensorRange range;
  const NavigatorConfig config = ranges();
  range.reset(config);
  // The tool turned 30 deg about down: its x and y axes are not north and east.
  const Eigen::Matrix3d c_bn = Eigen::AngleAxisd(30 * kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  InputReading in;
  in.clipped = 8u | 16u;  // gyros x and y
  const double dt = 0.0025;
  range.integrate(in, dt, c_bn);
  range.integrate(in, dt, c_bn);
  UnseenMotionNoise noise;
  range.add_to(noise);
  // Each axis: up to 1000 deg/s beyond the range for two readings, root mean square 1/sqrt(3) of it.
  const double per_axis = std::pow(2 * dt * (config.gyro_rate_max - config.gyro_range) / std::sqrt(3.0), 2);
  const Eigen::Vector3d x = c_bn.col(0), y = c_bn.col(1), z = c_bn.col(2);
  EXPECT_NEAR(along(noise.attitude, x), per_axis, 1e-9 * per_axis);
  EXPECT_NEAR(along(noise.attitude, y), per_axis, 1e-9 * per_axis);
  EXPECT_NEAR(along(noise.attitude, x - y), per_axis, 1e-9 * per_axis);  // as much across the diagonal
  EXPECT_NEAR(along(noise.attitude, z), 0.0, 1e-12);
  EXPECT_TRUE(noise.turn.isZero(0.0));  // a turn about one direction is a gap's, not this
  // Taken: the next epoch starts from nothing.
  UnseenMotionNoise next;
  range.add_to(next);
  EXPECT_TRUE(next.attitude.isZero(0.0));
}

TEST(SensorRange, AccelerometersClippedTogetherWidenTheVelocityAcrossTheirDiagonal) {
  SensorRange range;
  const NavigatorConfig config = ranges();
  range.reset(config);
  InputReading in;
  in.clipped = 1u | 2u;  // accelerometers x and y
  const double dt = 0.0025;
  range.integrate(in, dt, Eigen::Matrix3d::Identity());
  UnseenMotionNoise noise;
  range.add_to(noise);
  const double per_axis = std::pow(dt * (config.accel_shock_max - config.accel_range) / std::sqrt(3.0), 2);
  EXPECT_NEAR(along(noise.velocity, Eigen::Vector3d(1, -1, 0)), per_axis, 1e-9 * per_axis);
  EXPECT_NEAR(along(noise.velocity, Eigen::Vector3d(1, 1, 0)), per_axis, 1e-9 * per_axis);
  EXPECT_NEAR(along(noise.velocity, Eigen::Vector3d::UnitZ()), 0.0, 1e-12);
  EXPECT_NE(range.row_warning().find("accelerometer clipped"), std::string::npos);
}

}  // namespace
}  // namespace plumb::strapdown
