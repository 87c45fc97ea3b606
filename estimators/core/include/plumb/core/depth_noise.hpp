// The noise of the rig's depth reports as the data show it, for a user who did not state it: the
// second difference of successive reports (blind to a steady rate of penetration) over blocks of a
// few seconds, and a low quantile over the blocks seen, the quietest stretches. Shared by the
// navigator (its depth measurement noise) and the survey (how far a standing depth may wander).
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
  // Per-report standard deviation, m; none until kMinBlocks blocks were seen.
  std::optional<double> sd() const;
  std::size_t blocks() const { return blocks_.size(); }

  static constexpr double kBlockSeconds = 5.0;  // rig reports come about once a second
  static constexpr std::size_t kMinBlocks = 3;
  static constexpr double kQuantile = 0.25;

 private:
  std::vector<double> blocks_;
  std::vector<double> reports_;  // the last two
  bool last_row_had_depth_ = false;
  double t0_ = 0, sq_ = 0, terms_ = 0;
};

}  // namespace plumb
