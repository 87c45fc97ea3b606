// The conversions between the math libraries' types and the topic types lose nothing a topic can
// carry: an estimate through plumb/attitude and back is the same estimate.
#include <gtest/gtest.h>

#include "plumb/components/convert.hpp"

namespace plumb::components {
namespace {

TEST(Convert, AttitudeRoundTripKeepsEveryField) {
  for (int bits = 0; bits < 32; ++bits) {
    Estimate e;
    e.estimator = "compensated";
    e.t_start = 12.25;
    e.t_end = 22.25;
    e.inclination_deg = 89.5;
    e.azimuth_deg = 359.75;
    e.gravity_toolface_deg = 181.5;
    e.magnetic_toolface_deg = 3.25;
    e.rpm = 60.5;
    e.inclination_sd_deg = 0.01;
    e.azimuth_sd_deg = 0.2;
    e.toolface_sd_deg = 0.3;
    e.dip_deg = 45.5;
    e.total_g = 9.80665;
    e.total_b = 48.4;
    e.samples_used = 1000;
    e.valid = bits & 1;
    e.azimuth_valid = bits & 2;
    e.toolface_valid = bits & 4;
    e.rotating = bits & 8;
    e.partial_window = bits & 16;
    e.reason = bits ? "" : "platform rotating";
    const topics::Attitude a = to_topic(e, "tool 7");
    EXPECT_EQ(a.tool_id, "tool 7");
    const Estimate r = from_topic(a);
    EXPECT_EQ(r.estimator, e.estimator);
    EXPECT_NEAR(r.t_start, e.t_start, 1e-9);  // the topic carries whole nanoseconds
    EXPECT_NEAR(r.t_end, e.t_end, 1e-9);
    EXPECT_EQ(r.inclination_deg, e.inclination_deg);
    EXPECT_EQ(r.azimuth_deg, e.azimuth_deg);
    EXPECT_EQ(r.gravity_toolface_deg, e.gravity_toolface_deg);
    EXPECT_EQ(r.magnetic_toolface_deg, e.magnetic_toolface_deg);
    EXPECT_EQ(r.rpm, e.rpm);
    EXPECT_EQ(r.inclination_sd_deg, e.inclination_sd_deg);
    EXPECT_EQ(r.azimuth_sd_deg, e.azimuth_sd_deg);
    EXPECT_EQ(r.toolface_sd_deg, e.toolface_sd_deg);
    EXPECT_EQ(r.dip_deg, e.dip_deg);
    EXPECT_EQ(r.total_g, e.total_g);
    EXPECT_EQ(r.total_b, e.total_b);
    EXPECT_EQ(r.samples_used, e.samples_used);
    EXPECT_EQ(r.valid, e.valid);
    EXPECT_EQ(r.azimuth_valid, e.azimuth_valid);
    EXPECT_EQ(r.toolface_valid, e.toolface_valid);
    EXPECT_EQ(r.rotating, e.rotating);
    EXPECT_EQ(r.partial_window, e.partial_window);
    EXPECT_EQ(r.reason, e.reason);
  }
}

TEST(Convert, AnInvalidReasonTravelsWhole) {
  // The longest reasons the plugins give are over 63 characters; the display shows them whole.
  Estimate e;
  e.estimator = "compensated";
  e.reason = "radial magnetic field too weak against its noise to track the platform angle";
  EXPECT_EQ(from_topic(to_topic(e, "tool")).reason, e.reason);
  e.navigation = NavigationState{};
  e.reason = "aligning: waiting for the first still period of at least 2 s with the gyros quiet";
  EXPECT_EQ(to_navigation(e, "tool").reason, e.reason);
}

}  // namespace
}  // namespace plumb::components
