// A clipped shock's burst (ShockRebound): it opens at the first clipped accelerometer reading, ends
// kQuietReadings unclipped readings after the last, and then takes back exactly the velocity across
// the axis and the displacement across it since the burst opened, nothing along the axis.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "plumb/strapdown/shock_rebound.hpp"

namespace plumb::strapdown {
namespace {

TEST(ShockRebound, TakesBackWhatTheBurstMadeAcrossTheAxisOnly) {
  ShockRebound shocks;
  InputReading quiet, clipped;
  clipped.clipped = 2u;  // accelerometer y
  EXPECT_FALSE(shocks.starts(quiet));
  ASSERT_TRUE(shocks.starts(clipped));
  NavState before;
  before.p = Eigen::Vector3d(1, 2, 3);
  shocks.start(before);
  EXPECT_FALSE(shocks.starts(clipped));  // one burst at a time
  EXPECT_FALSE(shocks.ends(clipped));
  for (int k = 1; k < ShockRebound::kQuietReadings; ++k) EXPECT_FALSE(shocks.ends(quiet));
  EXPECT_FALSE(shocks.ends(clipped));  // clipped again: the count starts over
  for (int k = 1; k < ShockRebound::kQuietReadings; ++k) EXPECT_FALSE(shocks.ends(quiet));
  ASSERT_TRUE(shocks.ends(quiet));
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 1, 1).normalized();
  const Eigen::Vector3d lateral = Eigen::Vector3d(1, -1, 0).normalized();
  NavState after;
  after.v = 0.05 * axis + 0.8 * lateral;               // along: the rate of penetration; across: the shock's
  after.p = before.p + 0.002 * axis + 0.03 * lateral;  // and the displacement the clipped shock made
  const ShockRebound::Shift back = shocks.end(after, axis);
  EXPECT_LT((after.v + back.dv - 0.05 * axis).norm(), 1e-12);
  EXPECT_LT((after.p + back.dp - (before.p + 0.002 * axis)).norm(), 1e-12);
  EXPECT_FALSE(shocks.open());
}

}  // namespace
}  // namespace plumb::strapdown
