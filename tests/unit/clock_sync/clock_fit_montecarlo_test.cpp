// The depth clock's sigma against its error over 100 simulated rig days (label montecarlo: seconds).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "rig_day.hpp"

namespace plumb::clock_sync {
namespace {

TEST(ClockFit, ItsSigmaIsHonestOverManyDays) {
  // Over 100 six-hour days (about ten stops each) the errors divided by their sigma: about 95 % within 2, and sigma not inflated.
  int within2 = 0, n = 0;
  double z2 = 0, worst_offset = 0, worst_drift = 0;
  for (unsigned seed = 1; seed <= 100; ++seed) {
    test::RigDay day;
    day.seed = seed;
    day.hours = 6;
    day.depth_sd_m = 0.002 + 0.001 * (seed % 3);
    day.plan();
    auto f = day.fit();
    const auto& e = f.estimate();
    ASSERT_TRUE(e.has_value()) << "seed " << seed << ": " << f.why_not();
    const double err = e->offset_s - (day.offset_s + day.drift * e->t_ref_s);
    const double z = err / e->offset_sd_s;
    z2 += z * z;
    within2 += std::abs(z) <= 2;
    ++n;
    worst_offset = std::max(worst_offset, std::abs(err));
    worst_drift = std::max(worst_drift, std::abs(e->drift - day.drift));
  }
  const double rms_z = std::sqrt(z2 / n);
  std::printf("offset: worst error %.4f s, rms error/sigma %.2f, %d of %d within 2 sigma; drift: worst error %.2f ppm\n",
              worst_offset, rms_z, within2, n, worst_drift * 1e6);
  EXPECT_GE(within2, 90);
  EXPECT_GT(rms_z, 0.5);
  EXPECT_LT(rms_z, 1.5);
}

}  // namespace
}  // namespace plumb::clock_sync
