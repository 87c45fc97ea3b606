// Attitude windows missing between two that arrived: counted in windows, said once per gap.
#include <gtest/gtest.h>

#include "attitude_continuity.hpp"

namespace plumb::survey_component {
namespace {

TEST(AttitudeContinuity, BackToBackWindowsMissNothing) {
  AttitudeContinuity c;
  for (int i = 0; i < 10; ++i) EXPECT_EQ(c.add(i * 0.5, i * 0.5 + 0.499), 0u);
  EXPECT_EQ(c.gaps(), 0u);
  EXPECT_EQ(c.windows_missing(), 0u);
}

TEST(AttitudeContinuity, ARestartedHostLosesItsWindowsInProgress) {
  AttitudeContinuity c;
  c.add(0.0, 0.499);
  c.add(0.5, 0.999);
  EXPECT_EQ(c.add(3.0, 3.499), 4u);  // 1.0 .. 3.0 never came: 4 windows of 0.5 s
  EXPECT_EQ(c.gaps(), 1u);
  EXPECT_EQ(c.windows_missing(), 4u);
  EXPECT_NE(c.last_note().find("4 windows missing"), std::string::npos);
  EXPECT_EQ(c.add(2.0, 2.499), 0u);  // a step back is not a loss
  EXPECT_EQ(c.out_of_order(), 1u);
}

TEST(AttitudeContinuity, APartialWindowBeforeTheGapDoesNotInflateIt) {
  AttitudeContinuity c;
  c.add(0.0, 0.499);
  c.add(0.5, 0.699);                 // published short when the input went silent
  EXPECT_EQ(c.add(2.7, 3.199), 4u);  // 2.0 s missing: 4 windows of 0.5 s, not 10 of 0.2 s
}

TEST(AttitudeContinuity, APartialWindowIsNoGap) {
  AttitudeContinuity c;
  c.add(0.0, 0.499);
  EXPECT_EQ(c.add(0.6, 0.8), 0u);  // a tenth of a window lost in transit: less than half a window
  EXPECT_EQ(c.gaps(), 0u);
}

}  // namespace
}  // namespace plumb::survey_component
