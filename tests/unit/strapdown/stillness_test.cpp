// Stillness detectors: short stances (foot-mounted or hand-carried tools) at 400 Hz and 1 kHz,
// and the source's magnitude test against a turning tool.
#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

#include <gtest/gtest.h>

#include "plumb/strapdown/stillness.hpp"

namespace plumb::strapdown::test {
namespace {

struct Phase {
  double t0, t1;
  bool still;
};

// Walks: stances of 0.05-0.3 s between 0.6 s swings with strong, changing motion; MEMS noise.
void check_stances(double rate_hz, StillnessConfig::Mode mode) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.05, 0.3);
  const double dt = 1.0 / rate_hz;
  const double sigma_a = 0.06 / 60.0 / std::sqrt(dt), sigma_w = 0.3 * 3.14159265358979 / 180.0 / 60.0 / std::sqrt(dt);
  StillnessConfig c;
  c.mode = mode;
  c.window_s = 0.02;
  c.min_still_s = 0.03;
  c.sigma_a = sigma_a;
  c.sigma_w = sigma_w;
  c.gyro_tol = 1e-3;
  StillnessDetector detector(c);

  std::vector<Phase> phases;
  double t = 0;
  for (int k = 0; k < 40; ++k) {
    const double stance = u(rng);
    phases.push_back({t, t + 0.6, false});
    phases.push_back({t + 0.6, t + 0.6 + stance, true});
    t += 0.6 + stance;
  }
  std::size_t detected_stances = 0, false_still_samples = 0;
  std::size_t phase = 0;
  bool seen_in_phase = false;
  for (double s = 0; s < t; s += dt) {
    while (phase + 1 < phases.size() && s >= phases[phase].t1) {
      if (phases[phase].still && seen_in_phase) ++detected_stances;
      ++phase;
      seen_in_phase = false;
    }
    const bool still = phases[phase].still;
    StillnessInput in;
    in.t = s;
    const double wobble = std::sin(2 * 3.14159265358979 * 1.7 * s);
    in.f = Eigen::Vector3d(sigma_a * n(rng), sigma_a * n(rng), -9.81 + sigma_a * n(rng));
    in.w_minus_expected = Eigen::Vector3d(sigma_w * n(rng), sigma_w * n(rng), sigma_w * n(rng));
    if (!still) {
      in.f += Eigen::Vector3d(3.0 * wobble + n(rng), 2.0 * n(rng), 4.0 * wobble);
      in.w_minus_expected += Eigen::Vector3d(2.0 * wobble, 1.0 + 0.5 * n(rng), 0.5 * n(rng));
    }
    in.g = 9.81;
    const StillnessState st = detector.update(in);
    if (st.still && still) seen_in_phase = true;
    if (st.still && !still) ++false_still_samples;
  }
  if (phases.back().still && seen_in_phase) ++detected_stances;
  EXPECT_EQ(detected_stances, 40u) << "rate " << rate_hz;
  // Detection lags motion onset by at most a window: a few samples per swing.
  EXPECT_LT(false_still_samples, 40u * static_cast<std::size_t>(c.window_s * rate_hz + 2)) << "rate " << rate_hz;
}

TEST(Stillness, GlrtFindsShortStancesAt400HzAnd1kHz) {
  check_stances(400, StillnessConfig::Mode::Glrt);
  check_stances(1000, StillnessConfig::Mode::Glrt);
}

TEST(Stillness, MagnitudeFindsShortStances) { check_stances(400, StillnessConfig::Mode::Magnitude); }

// The magnitude detector (default window and minimum period) for a sensor of this noise per
// sample, its gyros quiet within 5 deg/h.
StillnessConfig magnitude_config(double sigma_a, double sigma_w) {
  StillnessConfig c;
  c.mode = StillnessConfig::Mode::Magnitude;
  c.sigma_a = sigma_a;
  c.sigma_w = sigma_w;
  c.gyro_tol = 5.0 * 3.14159265358979 / 180.0 / 3600.0;
  return c;
}

// A tool turning slowly and steadily (a sliding build of 8 deg/30 m at 0.05 m/s turns at
// 2.3e-4 rad/s, below one sample's noise of a MEMS gyro) is not still: the period-long rate test
// ends the period though every short window looks quiet.
TEST(Stillness, SlowSteadyTurnIsNotStill) {
  StillnessDetector detector(magnitude_config(0.01, 8.7e-4));
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  std::size_t still_samples = 0, total = 0;
  for (double t = 0; t < 120; t += 0.01, ++total) {
    StillnessInput in;
    in.t = t;
    in.f = Eigen::Vector3d(0.01 * n(rng), 0.01 * n(rng), -9.81 + 0.01 * n(rng));
    in.w_minus_expected = Eigen::Vector3d(2.3e-4 + 8.7e-4 * n(rng), 8.7e-4 * n(rng), 8.7e-4 * n(rng));
    in.g = 9.81;
    if (detector.update(in).still) ++still_samples;
  }
  EXPECT_LT(static_cast<double>(still_samples), 0.2 * static_cast<double>(total));
}

// A slide that builds turns a tactical gyro just past its window limit: the windows are not quite
// quiet, so the period-long means are held, not restarted, and at the stop that follows they still
// hold the force of the slide's start (0.8 deg of build here: 0.14 m/s^2). The stop must be seen
// within seconds, not after the 20-40 s those means take to forget (on a simulated tactical run a
// 60 s pipe connection looked like 19 s and the tally skipped a joint).
TEST(Stillness, StopAfterABuildingSlideIsSeenWithinSeconds) {
  StillnessDetector detector(magnitude_config(0.001, 2e-5));
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  // 9e-5 rad/s: between one and three times the window's gyro limit, as a tactical gyro read at
  // 10 Hz sees a build of 3 deg/30 m at 0.05 m/s; the means take 23 s to forget the slide's start.
  const double build = 9e-5, slide_end = 160, g = 9.81;
  double first_still = -1;
  std::size_t still_in_slide = 0;
  for (double t = 0; t < 240; t += 0.1) {
    const bool sliding = t < slide_end;
    const double theta = build * std::min(t, slide_end);
    StillnessInput in;
    in.t = t;
    in.f = Eigen::Vector3d(g * std::sin(theta), 0, -g * std::cos(theta)) +
           0.001 * Eigen::Vector3d(n(rng), n(rng), n(rng));
    in.w_minus_expected = Eigen::Vector3d(sliding ? build : 0.0, 0, 0) + 2e-5 * Eigen::Vector3d(n(rng), n(rng), n(rng));
    in.g = g;
    const bool still = detector.update(in).still;
    if (still && sliding) ++still_in_slide;
    if (still && !sliding && first_still < 0) first_still = t;
  }
  EXPECT_EQ(still_in_slide, 0u);
  ASSERT_GE(first_still, slide_end);
  EXPECT_LT(first_still - slide_end, 8.0);
}

// A rig's depth report: the true depth plus white noise, quantized to a tenth of a foot, once a
// second and held on every reading until the next.
struct RigDepth {
  std::mt19937_64 rng{11};
  std::normal_distribution<double> noise;
  double held = 0, last_report = -1e9;
  explicit RigDepth(double sd_m) : noise(0.0, sd_m) {}
  double at(double t, double depth) {
    if (t - last_report >= 1.0) {
      held = std::round((depth + noise(rng)) / 0.03048) * 0.03048;
      last_report = t;
    }
    return held;
  }
};

// A still tool or one that slides at a steady rate: gravity and the sensors' noise alone. The
// depth's noise stated as the rounding leaves it (at least 5 cm in 0.1 ft steps), the range limit
// as the navigator sets it (8 sigma).
struct DepthRun {
  StillnessDetector detector;
  std::mt19937_64 rng{5};
  std::normal_distribution<double> n{0.0, 1.0};
  RigDepth rig;
  static StillnessConfig config(double stated_sd_m) {
    StillnessConfig c = magnitude_config(0.002, 5e-5);
    c.depth_sd_m = stated_sd_m;
    c.depth_tol_m = 8 * stated_sd_m;
    return c;
  }
  explicit DepthRun(double depth_sd_m) : detector(config(std::hypot(depth_sd_m, 0.03048 / std::sqrt(12.0)))), rig(depth_sd_m) {}
  bool step(double t, double depth) {
    StillnessInput in;
    in.t = t;
    in.f = Eigen::Vector3d(0, 0, -9.81) + 0.002 * Eigen::Vector3d(n(rng), n(rng), n(rng));
    in.w_minus_expected = 5e-5 * Eigen::Vector3d(n(rng), n(rng), n(rng));
    in.g = 9.81;
    in.depth_m = rig.at(t, depth);
    return detector.update(in).still;
  }
};

// A slide at a steady rate moves neither the accelerometers nor the gyros, and each second's
// depth by less than its noise: the mean test ends the still period after some seconds, and the
// period must not start again while the depth goes on (the navigator held the velocity at zero
// through a whole slide of an outside run read without sensor noise, and its azimuth missed the
// slide's turn). The stop after it is seen once the recent reports' line is flat and slower than
// the one before (a 5 cm/s slide under 2 cm of noise), or else once the whole window's line is
// flat (3 cm/s under 4.4 cm, the outside run's: 10 s).
TEST(Stillness, SteadySlideTheDepthSeesStaysMoving) {
  for (const auto& [rop, depth_sd, stop_seen_within_s] : {std::tuple{0.03, 0.044, 12.0}, std::tuple{0.05, 0.02, 6.0}}) {
    DepthRun run(depth_sd);
    const double slide_start = 40, slide_end = 210;
    std::size_t still_late_in_slide = 0, slide_samples = 0;
    double first_still_after = -1;
    for (double t = 0; t < 300; t += 0.01) {
      const double depth = 100 + rop * std::clamp(t - slide_start, 0.0, slide_end - slide_start);
      const bool still = run.step(t, depth);
      if (t > slide_start + 30 && t < slide_end) {
        ++slide_samples;
        if (still) ++still_late_in_slide;
      }
      if (t > slide_end && still && first_still_after < 0) first_still_after = t;
    }
    EXPECT_EQ(still_late_in_slide, 0u) << rop << " m/s: of " << slide_samples << " samples after the slide's first 30 s";
    ASSERT_GT(first_still_after, slide_end) << rop << " m/s";
    EXPECT_LT(first_still_after - slide_end, stop_seen_within_s) << rop << " m/s";
  }
}

// A floating rig's swell on the depth of a still tool (0.5 m at 10 s, beside the reports' noise)
// is no slide. The depth's mean test ends a period now and then on such a swell (91 % of the time
// still, with the trend as without it); the trend that follows must not keep it moving: its sigma
// counts the reports' scatter about its line (with the stated noise alone, 80 %).
TEST(Stillness, SwellOnTheDepthOfAStillToolIsNoSlide) {
  DepthRun run(0.044);
  std::size_t still_samples = 0, total = 0;
  for (double t = 0; t < 300; t += 0.01, ++total) {
    if (run.step(t, 100 + 0.5 * std::sin(2 * 3.14159265358979 * t / 10))) ++still_samples;
  }
  EXPECT_GT(static_cast<double>(still_samples), 0.88 * static_cast<double>(total)) << still_samples << " of " << total;
}

}  // namespace
}  // namespace plumb::strapdown::test
