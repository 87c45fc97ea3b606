// Stillness detectors: short stances (foot-mounted or hand-carried tools) at 400 Hz and 1 kHz,
// and the source's magnitude test against a turning tool.
#include <cmath>
#include <random>

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

}  // namespace
}  // namespace plumb::strapdown::test
