// Monte Carlo over many random source-form packages (ctest label montecarlo): the worst true
// inclination error after calibration over orientations and temperatures that are not the
// stations, per procedure and output, against the accuracy the README states.
#include <algorithm>
#include <cstdlib>

#include <gtest/gtest.h>

#include "source_form_support.hpp"

namespace plumb {
namespace {

using namespace test::source;

int packages() {
  const char* n = std::getenv("PLUMB_MONTECARLO_PACKAGES");   // more for a longer study
  return n ? std::max(1, std::atoi(n)) : 20;
}

struct Summary {
  int runs = 0, refused = 0;
  double worst_after = 0, min_before = 1e9, max_before = 0, worst_ratio = 0;
};

void add(Summary& s, const Trial& t) {
  ++s.runs;
  if (!t.outcome.ok()) {
    ++s.refused;
    std::printf("  refused: %s\n", t.outcome.error.c_str());
    return;
  }
  s.worst_after = std::max(s.worst_after, t.after_deg);
  s.min_before = std::min(s.min_before, t.before_deg);
  s.max_before = std::max(s.max_before, t.before_deg);
  s.worst_ratio = std::max(s.worst_ratio, t.after_deg / t.outcome.result->predicted.inclination_deg);
}

void print(const char* what, const Summary& s) {
  std::printf("%s: %d packages, %d refused; before %.3f..%.3f deg; worst after %.6f deg; worst true/predicted %.2f\n",
              what, s.runs, s.refused, s.min_before, s.max_before, s.worst_after, s.worst_ratio);
}

TEST(SourceFormMonteCarlo, SixPosition) {
  for (bool pulses : {false, true}) {
    Summary s;
    for (int k = 0; k < packages(); ++k) {
      std::mt19937_64 rng(8000 + 2 * static_cast<std::uint64_t>(k) + pulses);
      const Package pkg = Package::random(rng, pulses, 2);
      Rig rig;
      const Trial t = six_position_trial(pkg, rig, six_positions(60), 9000 + static_cast<std::uint64_t>(k));
      EXPECT_TRUE(t.outcome.ok()) << t.outcome.error;
      expect_honest(t, "6pos package " + std::to_string(k), 0.0005);
      add(s, t);
    }
    print(pulses ? "6-position, pulses" : "6-position, volts", s);
  }
}

TEST(SourceFormMonteCarlo, TwentyFourPositionWithTemperature) {
  for (bool pulses : {false, true}) {
    Summary s;
    for (int k = 0; k < packages() / 2; ++k) {
      std::mt19937_64 rng(8500 + 2 * static_cast<std::uint64_t>(k) + pulses);
      const Package pkg = Package::random(rng, pulses, 1 + k % 3);
      Rig rig;
      std::uniform_real_distribution<double> tilt(-0.05, 0.05);
      rig.tilt_x_deg = tilt(rng);
      rig.tilt_y_deg = tilt(rng);
      const Trial t = twenty_four_trial(pkg, rig, {25, 65, 105, 145, 185, 225}, 30, 9500 + static_cast<std::uint64_t>(k));
      EXPECT_TRUE(t.outcome.ok()) << t.outcome.error;
      expect_honest(t, "24pos package " + std::to_string(k), 0.0005);
      add(s, t);
    }
    print(pulses ? "24-position, pulses" : "24-position, volts", s);
  }
}

}  // namespace
}  // namespace plumb
