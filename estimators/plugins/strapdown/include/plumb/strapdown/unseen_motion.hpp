// What a drilling tool's sensors cannot see without measured depth or a pipe tally: a slide that
// starts and ends smoothly and runs straight at a steady speed leaves the accelerometers and gyros
// as a stop does, so every stop may be one. The filter's zero-velocity updates then hold a speed
// that was not zero: its position, and what its updates make of the unseen speed-up, are only as
// good as the largest rate of penetration allows. This part says so to the filter, as process noise
// over each such stop, and to the user, once and on the rows: the pipe tally is the remedy.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/strapdown/navigator_config.hpp"
#include "plumb/strapdown/stillness.hpp"
#include "plumb/strapdown/unseen_motion_noise.hpp"

namespace plumb::strapdown {

class UnseenMotion {
 public:
  void reset(const NavigatorConfig& config);
  // At alignment: whether this tool can slide (a drilling tool: it moves along its own axis).
  void at_alignment(double t, bool drilling_tool);
  // A reading with depth at t (before alignment too): depth measures the along-hole motion while
  // such rows keep coming (within the age of a held report), as a pipe tally does at connections.
  void note_depth(double t) { last_depth_t_ = t; }
  // The noise of the epoch that ends at t (dt long), the tool axis in NED at its start; still: the
  // filter's stillness decision at t.
  UnseenMotionNoise at_epoch(const Eigen::Vector3d& axis, const StillnessState& still, double t, double dt);
  // What the rows say while the along-hole motion is not measured (empty otherwise).
  std::string row_warning() const { return unmeasured_ ? warning_ : std::string(); }
  std::vector<std::string> take_notices();

 private:
  NavigatorConfig config_;
  bool drilling_tool_ = false;
  bool unmeasured_ = false;
  bool notice_given_ = false;
  double since_ = 0;  // when the stop in progress began to hide a slide (its start, or the alignment)
  bool in_stop_ = false;
  std::optional<double> last_depth_t_;
  std::string warning_;
  std::vector<std::string> notices_;
};

}  // namespace plumb::strapdown
