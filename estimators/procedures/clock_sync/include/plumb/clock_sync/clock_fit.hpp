// The depth feed's clock against the sensor stream's, from the still runs both saw:
//   t_depth = t_sensor + offset + drift * (t_sensor - t_ref)
// Candidate offsets come from every pair of runs of similar duration (one depth run, one sensor run:
// the cross-correlation of the two still/moving series, evaluated only where it can peak); the
// offset that matches the most runs wins, and must win alone (a periodic pattern of stops that two
// offsets explain equally waits for a stop that tells them apart). A run that an offset puts where
// the other stream was watching and saw no stop counts against that offset (coverage): a stream
// that began later, or whose last stops are not settled yet, is not held against any. The matched midpoints then give
// offset and drift by least squares (drift with a prior, stated), re-matched until stable; sigma
// from the residuals, never below the timing floor.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>

#include "plumb/clock_sync/still_run.hpp"

namespace plumb::clock_sync {

struct ClockFitOptions {
  double match_tolerance_s = 2;       // midpoints this close (after the offset) are the same stop
  double duration_tolerance_s = 20;   // and durations this close
  double duration_tolerance_rel = 0.25;  // or this fraction of the longer, whichever is larger
  std::size_t min_matched = 2;        // runs matched before an estimate is given
  double drift_prior_sd = 100e-6;     // a clock's rate error: 0 +- this (quartz is within 50 ppm)
  double timing_floor_s = 0.02;       // sigma of one midpoint at best (report interval, blocks)
  std::size_t max_runs = 200;         // runs kept per stream (the most recent)
};

struct ClockEstimate {
  double offset_s = 0;       // depth clock - sensor clock at t_ref_s
  double drift = 0;          // depth clock's rate error, s/s (1e-6 = 1 ppm)
  double t_ref_s = 0;        // sensor clock: the matched runs' mean
  double offset_sd_s = 0;
  double drift_sd = 0;
  double residual_sd_s = 0;  // of the matched midpoints about the fit
  std::size_t matched = 0;   // still runs matched
  std::size_t candidates_tied = 0;  // other offsets with as many matches (0: unique)
  // A depth stamp on the sensor clock.
  double sensor_time(double t_depth_s) const;
  // The offset at a sensor time.
  double offset_at(double t_sensor_s) const { return offset_s + drift * (t_sensor_s - t_ref_s); }
};

// One line saying an estimate (or the lack of one), for logs and status.
std::string describe(const std::optional<ClockEstimate>& e, std::size_t depth_runs, std::size_t sensor_runs);

class ClockFit {
 public:
  explicit ClockFit(ClockFitOptions options = {});
  void add_depth_run(const StillRun& r);
  void add_sensor_run(const StillRun& r);
  // Where each stream could have given a run (its own clock): from its first observation to the
  // time up to which its runs are settled. Used at the next estimate; without it no run counts
  // against an offset.
  void set_coverage(double depth_from_s, double depth_until_s, double sensor_from_s, double sensor_until_s);
  // The estimate from every run so far; nothing until min_matched runs match one offset alone.
  // Recomputed only after a new run.
  const std::optional<ClockEstimate>& estimate();
  std::size_t depth_runs() const { return depth_.size(); }
  std::size_t sensor_runs() const { return sensor_.size(); }
  // Why there is no estimate (empty when there is one).
  const std::string& why_not() const { return why_not_; }

 private:
  void compute();

  ClockFitOptions options_;
  std::deque<StillRun> depth_, sensor_;
  double depth_from_ = 0, depth_until_ = -1, sensor_from_ = 0, sensor_until_ = -1;
  bool dirty_ = false;
  std::optional<ClockEstimate> estimate_;
  std::string why_not_ = "no still run seen yet";
};

}  // namespace plumb::clock_sync
