// Whether the depth reports show the tool going along the hole: the slope of their least-squares
// line against its own sigma. A slide at a steady rate of penetration moves neither the
// accelerometers nor the gyros, and each second's depth changes by less than the reports' noise,
// so the stillness tests on one second of depth pass it; the line through kWindowS of reports does
// not (3 cm/s under 5 cm of noise: 44 sigma). A stop after the slide is seen sooner than that
// window allows when the line through the last kRecentS is flat and its slope differs from the
// line's before it. Each sigma counts the larger of the stated noise and the reports' own scatter
// about their line, so that a floating rig's swell (decimetres at 6-16 s) widens it instead of
// reading as motion. The window spans two or more of the swell's periods: with 20 s, on the
// navigator's Monte Carlo family of rig depth, the stop after a slide came a second later on one
// MEMS run, at the azimuth's largest error (0.515 deg against 0.496 without the trend; 0.492 with
// 40 s).
#pragma once

#include <cstddef>
#include <utility>

#include "plumb/strapdown/ring_queue.hpp"

namespace plumb::strapdown {

class DepthTrend {
 public:
  static constexpr double kWindowS = 40;
  static constexpr double kRecentS = 6;
  static constexpr double kSlopeSigmas = 4;
  static constexpr std::size_t kMinReports = 5;

  void clear();
  // One reading's depth: kept when a tenth of a second has passed since the last one kept and it
  // differs from it, or a second has (a rig's report held on every row counts once a second; a
  // depth on every reading of a 400 Hz tool, ten times a second).
  void add(double t, double depth);
  // Whether the reports of the window that ends at t show motion, for `noise_sd` per report: false
  // with fewer than kMinReports (nothing to judge: the caller's other tests decide). Judged again
  // only when a report was kept or a second has passed; the answer in between is the last one.
  bool moving(double t, double noise_sd);
  // The same test on the window's reports since t_from alone (a still period's own reports).
  bool moved_since(double t_from, double noise_sd) const;

 private:
  // Least-squares sums of (t - t0, depth - d0).
  struct Sums {
    double n = 0, x = 0, y = 0, xx = 0, xy = 0, yy = 0;
    void add(double px, double py, double sign);
    Sums operator+(const Sums& o) const { return {n + o.n, x + o.x, y + o.y, xx + o.xx, xy + o.xy, yy + o.yy}; }
  };
  struct Line {
    double slope = 0, sd = 0;
  };
  static bool fit(const Sums& s, double noise_sd, Line& line);
  bool judge(double t, double noise_sd);
  void drop_before(double t);
  void rebase();
  // The window's reports, older (kWindowS to kRecentS ago) and recent (the last kRecentS).
  RingQueue<std::pair<double, double>> older_, recent_;
  Sums older_sums_, recent_sums_;
  double t0_ = 0, d0_ = 0;
  double last_t_ = -1e300, last_depth_ = 0;
  double judged_t_ = -1e300;
  bool judged_moving_ = false;
};

}  // namespace plumb::strapdown
