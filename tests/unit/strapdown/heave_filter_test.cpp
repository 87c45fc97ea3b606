// The swell on a floating rig's depth reports (HeaveFilter), against reports made here with a known
// swell, drilling trend and noise: a swell is found, at its period, and taken out to a fraction of
// its size, on a standing tool and while drilling; white noise and a drilling trend's starts and
// stops are no swell; a standing tool's depth comes out as its reports' mean, not one report.
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "plumb/strapdown/heave_filter.hpp"

namespace plumb::strapdown {
namespace {

constexpr double kHeavePi = 3.14159265358979323846;

struct HeaveSea {
  double amplitude_m = 0, period_s = 10, phase = 0.7;
  double swell(double t) const { return amplitude_m * std::sin(2 * kHeavePi * t / period_s + phase); }
};

// The tool's true depth: standing 60 s, drilling 120 s at 0.03 m/s (a 10 s ramp at each end), and
// so on; still where the tool stands.
struct HeaveDrilling {
  bool drills = true;
  double depth(double t) const {
    if (!drills) return 1000;
    const double cycle = 180, at = std::fmod(t, cycle), done = std::floor(t / cycle) * 0.03 * 110;
    if (at < 60) return 1000 + done;
    const double moving = std::min(at - 60, 120.0);
    // A ramp of 10 s: the speed rises and falls linearly.
    const auto distance = [](double s) {
      if (s < 10) return 0.03 * s * s / 20;
      if (s < 110) return 0.03 * 5 + 0.03 * (s - 10);
      const double r = s - 110;
      return 0.03 * 105 + 0.03 * (r - r * r / 20);
    };
    return 1000 + done + distance(moving);
  }
  bool still(double t) const { return !drills || std::fmod(t, 180.0) < 60; }
};

struct SwellRun {
  double swell_rms_error = 0, swell_rms = 0;  // over the last half of the run, at the reports
  double found_share = 0;                     // of the reports in the last half
  double period_s = 0;
  double max_swell_taken = 0;
};

// 1 Hz reports for `seconds`, with white noise of noise_m (the depth_sd the navigator gives is the
// swell's rms and the noise together, as stated or measured).
SwellRun run_reports(const HeaveSea& sea, const HeaveDrilling& drilling, double noise_m, double seconds, unsigned seed) {
  HeaveFilter filter;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_m);
  const double depth_sd = std::hypot(sea.amplitude_m / std::sqrt(2.0), noise_m);
  SwellRun r;
  double n = 0, e2 = 0, s2 = 0, found = 0;
  for (double t = 0; t < seconds; t += 1.0) {
    filter.report(t, drilling.depth(t) + sea.swell(t) + noise(rng), drilling.still(t), depth_sd);
    r.max_swell_taken = std::max(r.max_swell_taken, std::abs(filter.swell()));
    if (t < seconds / 2) continue;
    n += 1;
    found += filter.found();
    e2 += (filter.swell() - sea.swell(t)) * (filter.swell() - sea.swell(t));
    s2 += sea.swell(t) * sea.swell(t);
  }
  r.swell_rms_error = std::sqrt(e2 / n);
  r.swell_rms = std::sqrt(s2 / n);
  r.found_share = found / n;
  r.period_s = filter.period_s().value_or(0);
  return r;
}

TEST(HeaveFilter, ASwellOnAStandingToolIsFoundAndTakenOut) {
  for (const double period : {6.5, 10.0, 15.5}) {
    HeaveSea sea{0.2, period};
    const SwellRun r = run_reports(sea, HeaveDrilling{false}, 0.01, 900, 3);
    std::printf("standing, 0.2 m swell at %.1f s: found on %.0f %% of reports, period %.0f s, swell left %.3f m rms of %.3f\n",
                period, 100 * r.found_share, r.period_s, r.swell_rms_error, r.swell_rms);
    EXPECT_GT(r.found_share, 0.99) << period;
    EXPECT_NEAR(r.period_s, period, 1.0) << period;
    // (What is left is mostly what the models take for the reports' own noise: kWhiteShare of
    // depth_sd, 4 cm here, which they do not follow.)
    EXPECT_LT(r.swell_rms_error, 0.25 * r.swell_rms) << period;
  }
}

TEST(HeaveFilter, ASwellWhileDrillingIsTakenOut) {
  for (const double period : {7.0, 12.0}) {
    const SwellRun r = run_reports(HeaveSea{0.25, period}, HeaveDrilling{}, 0.02, 1800, 5);
    std::printf("drilling, 0.25 m swell at %.0f s: found on %.0f %% of reports, swell left %.3f m rms of %.3f\n", period,
                100 * r.found_share, r.swell_rms_error, r.swell_rms);
    EXPECT_GT(r.found_share, 0.95) << period;
    EXPECT_LT(r.swell_rms_error, 0.3 * r.swell_rms) << period;
  }
}

// A land rig: white noise on the reports, and drilling's starts and stops, are no swell: nothing is
// taken out of any report, over several seeds.
TEST(HeaveFilter, NoiseAndDrillingAreNoSwell) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    for (const double noise : {0.01, 0.05}) {
      const SwellRun r = run_reports(HeaveSea{}, HeaveDrilling{}, noise, 1800, seed);
      EXPECT_EQ(r.max_swell_taken, 0.0) << "seed " << seed << ", noise " << noise;
    }
  }
}

// A land rig whose reports are quieter than the depth's stated noise (1.8 cm, read to the
// centimetre, against 5 cm stated, as a datasheet may give it): no swell either. The swell models'
// white noise is a share of the stated figure, and against a no-swell model that takes the whole
// figure for white noise, the slowest swell (16 s) won by that smaller noise alone, within the first
// minute, on 8 of 20 outside runs.
TEST(HeaveFilter, ReportsQuieterThanStatedAreNoSwell) {
  const HeaveDrilling drilling;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    HeaveFilter filter;
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.018);
    double max_swell = 0;
    for (double t = 0; t < 1800; t += 1.0) {
      filter.report(t, std::round((drilling.depth(t) + noise(rng)) * 100) / 100, drilling.still(t), 0.05);
      max_swell = std::max(max_swell, std::abs(filter.swell()));
    }
    EXPECT_EQ(max_swell, 0.0) << "seed " << seed;
  }
}

// Where the tool stands, its depth is the mean of the reports, swell and noise averaged out: within
// a few centimetres of the truth after a minute of a 0.3 m swell, where one report is off by up to
// 0.3 m.
TEST(HeaveFilter, AStandingToolsDepthIsItsReportsMean) {
  HeaveFilter filter;
  const HeaveSea sea{0.3, 9.0, 2.0};
  for (double t = 0; t < 60; t += 1.0) filter.report(t, 1000 + sea.swell(t), true, 0.3 / std::sqrt(2.0));
  ASSERT_TRUE(filter.depth());
  EXPECT_NEAR(*filter.depth(), 1000.0, 0.04);
}

}  // namespace
}  // namespace plumb::strapdown
