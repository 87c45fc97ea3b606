// The noise of the rig's depth reports as the data show it, for a user who did not state it, by two
// statistics, each over blocks and taken at a low quantile over the blocks seen (the quietest
// stretches), the larger of the two counting:
// - the second difference of successive reports over blocks of a few seconds: blind to a steady
//   rate of penetration, ready early, but blind too to what changes slowly against the reports'
//   spacing: a floating rig's heave (the compensator's residual, decimetres at swell periods of
//   6-16 s) moves the second difference of 1 Hz reports by a sixth of its size;
// - the spread about a straight line over half a minute of reports in which the depth stood (the
//   line's change over the block within kHeldLineChange of that spread): a swell of up to 16 s is
//   not a line (a line takes 5 % of its rms at most); the start or end of drilling in a block, a
//   kink that a line would call noise, changes the depth by far more than its spread about a line.
// The navigator takes the larger (its depth measurement noise); the survey's station detector (how
// far a standing depth may wander) the second differences alone, which its tests were built on.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace plumb {

class DepthNoiseFloor {
 public:
  // One row of a stream in time order, with its depth when the row carries one. A report is a
  // depth that differs from the row before, or the first after rows without one: a rig's report
  // held (repeated) on every row until the next one counts once.
  void add(double t, std::optional<double> depth);
  // Per-report standard deviation, m: the larger of the two statistics, none until either is ready.
  std::optional<double> sd() const;
  // Each statistic alone (none until kMinBlocks, kMinLineBlocks blocks).
  std::optional<double> second_difference_sd() const;
  std::optional<double> line_sd() const;
  std::size_t blocks() const { return blocks_.size() + line_blocks_.size(); }

  static constexpr double kBlockSeconds = 5.0;  // rig reports come about once a second
  static constexpr std::size_t kMinBlocks = 3;
  static constexpr double kLineBlockSeconds = 30.0;
  static constexpr std::size_t kMinLineBlocks = 1;
  static constexpr double kMinLineReports = 10;
  static constexpr double kHeldLineChange = 2;
  static constexpr double kQuantile = 0.25;

 private:
  // Least-squares sums of one block's reports, time from the block's first.
  struct LineSums {
    double n = 0, t0 = 0, t = 0, d0 = 0, d = 0, tt = 0, td = 0, dd = 0, last = 0;
    void add(double t_s, double depth);
    // The spread about the line, when the line's change over the block is within kHeldLineChange
    // of it.
    std::optional<double> held_residual_sd() const;
  };
  std::vector<double> blocks_, line_blocks_;
  LineSums line_;
  std::vector<double> reports_;  // the last two
  bool last_row_had_depth_ = false;
  double t0_ = 0, sq_ = 0, terms_ = 0;
};

}  // namespace plumb
