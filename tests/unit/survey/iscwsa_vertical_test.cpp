// The ISCWSA model's vertical form (inclination below the model's limit, 1e-4 deg) is the limit of
// its regular form: a straight well drilled at 2e-4 deg, just above the limit, must give the same
// covariance at every station as the same well at 0 deg. Checked where the two forms are the same
// course by course (azimuth 0; the north misalignment; ABXY-TI2 with revision 4's derivatives,
// revision 5 counting the whole first course against it in the vertical form only), and on courses
// of 9 m, shorter than the 10 m below which XYM3E is weighted up by sqrt(10 m / course).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/survey/iscwsa.hpp"

namespace plumb::survey::iscwsa {
namespace {

std::vector<Station> straight_well(double inclination_deg, double course_m, int courses) {
  std::vector<Station> s;
  for (int k = 0; k <= courses; ++k) {
    const double md = k * course_m;
    s.push_back({md, inclination_deg, 0.0, 0.0, md * std::cos(inclination_deg * 3.14159265358979323846 / 180)});
  }
  return s;
}

void expect_continuous(const ToolCode& tool, double course_m) {
  const Field field{9.80665, 50000, 72, 1e-4};
  const Result vertical = propagate(straight_well(0, course_m, 12), tool, field);
  const Result inclined = propagate(straight_well(2e-4, course_m, 12), tool, field);
  for (std::size_t t = 0; t < tool.terms.size(); ++t) {
    for (std::size_t k = 1; k < vertical.total.size(); ++k) {
      const Eigen::Matrix3d& v = vertical.per_term[t][k];
      const Eigen::Matrix3d& i = inclined.per_term[t][k];
      // 1e-4 of the variance: the regular form differs by O(inclination * tan(dip)), 1e-5 here.
      EXPECT_NEAR(v(0, 0), i(0, 0), 1e-4 * i(0, 0) + 1e-12) << tool.terms[t].code << " NN at station " << k;
      EXPECT_NEAR(v(1, 1), i(1, 1), 1e-4 * i(1, 1) + 1e-12) << tool.terms[t].code << " EE at station " << k;
      EXPECT_GT(v.trace(), 0) << tool.terms[t].code << " at station " << k;
    }
  }
}

TEST(IscwsaVertical, VerticalFormIsTheLimitOfTheRegularFormRevision4) {
  ToolCode tool{"vertical-terms rev4", 4, 0.000572615, {}};
  tool.terms = {{"ABXY-TI2S", "ABXY-TI2", 0.004, "m/s2", Propagation::Systematic},
                {"XYM3", "XYM3", 0.1, "deg", Propagation::Systematic},
                {"XYM3R", "XYM3", 0.1, "deg", Propagation::Random}};
  expect_continuous(tool, 30);
  expect_continuous(tool, 9);
}

TEST(IscwsaVertical, VerticalFormIsTheLimitOfTheRegularFormOnShortCourses) {
  ToolCode tool{"vertical-terms rev5", 5, 0.000572615, {}};
  tool.terms = {{"XYM3E", "XYM3E", 0.3, "deg", Propagation::Random},
                {"XYM3ES", "XYM3E", 0.3, "deg", Propagation::Systematic}};
  expect_continuous(tool, 30);
  expect_continuous(tool, 9);
}

}  // namespace
}  // namespace plumb::survey::iscwsa
