// Still runs of the rig's measured depth: reports that stay within a tolerance of each other for at
// least min_still_s, with moving reports before and after. Fed one report at a time, in time order.
// A noisy report that breaks a stand in two does not make two stops: consecutive still pieces at
// the same level are one run. The run's ends are then placed symmetrically: the first and last
// report within half the tolerance of the run's median, so that a string slowing down and one
// speeding up are caught at the same distance from standing (the midpoint keeps no lag from the
// tolerance). Better still, where the string moved steadily before and after (drilling), each end is
// where the line through those reports meets the standing level: a ramp at both ends moves both
// ends inwards by half its length, and the midpoint stays where it was, to within the reports'
// noise averaged over fit_span_s. A run is given once fit_span_s of reports after it are in.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "plumb/clock_sync/still_run.hpp"

namespace plumb::clock_sync {

struct DepthStillnessOptions {
  double tolerance_m = 0.02;  // spread of a standing string's reports (above the depth's noise)
  double min_still_s = 5;     // shorter pauses are not connections
  double max_gap_s = 10;      // a silence longer than this ends what is known about the run
  double fit_span_s = 60;     // steady motion fitted on each side of a run (back to the stand before)
};

class DepthStillness {
 public:
  explicit DepthStillness(DepthStillnessOptions options = {});
  // A still run that is now known to have ended, else nothing.
  std::optional<StillRun> add(double t_s, double depth_m);
  std::size_t reports() const { return reports_; }
  // Coverage for ClockFit::set_coverage: the first report, and the time before which every run
  // has been given (a run is given fit_span_s + 2 min_still_s after its end).
  double first_t() const { return first_t_; }
  double settled_until() const { return last_t_ - options_.fit_span_s - 2 * options_.min_still_s - 1; }

 private:
  // Reports within the tolerance of each other, begun after `prev_t` (the report before them).
  struct DepthPiece {
    std::vector<std::pair<double, double>> reports;  // (time, depth)
    double prev_t = 0, after_t = 0;                  // the reports just before and just after
    bool after_motion = false;                       // the depth moved before it
    double lo = 0, hi = 0;
    std::vector<std::pair<double, double>> before;   // reports up to fit_span_s before it
    double duration_s() const { return reports.back().first - reports.front().first; }
  };
  void start_piece(double t_s, double depth_m, double prev_t, bool after_motion);
  double median_of(const DepthPiece& p) const;
  StillRun placed(const DepthPiece& p, const std::vector<std::pair<double, double>>& following) const;
  std::optional<StillRun> settle(double t_s, bool force);

  DepthStillnessOptions options_;
  bool have_ = false;
  double last_t_ = 0, first_t_ = 0;
  DepthPiece piece_;                  // being filled
  std::optional<DepthPiece> pending_; // a finished still piece, waiting to see whether the stand goes on
  std::optional<DepthPiece> leaving_; // a stand that ended, collecting the reports that follow it
  std::vector<std::pair<double, double>> after_;  // those reports
  std::vector<std::pair<double, double>> recent_; // the last fit_span_s of reports
  double motion_since_t_ = 0;                     // the last report of the stand before
  std::size_t reports_ = 0;
};

}  // namespace plumb::clock_sync
