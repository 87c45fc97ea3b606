#include "plumb/strapdown/unseen_motion.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "plumb/strapdown/navigator_common.hpp"

namespace plumb::strapdown {

namespace {

// How often a drilling string changes its speed, on average (s): a slide starts or ends every two
// minutes or so (the plumb simulator's reference run and the outside runs change it 6-10 times in
// 16 minutes). A random walk of v_max per this long is what the unseen speed-ups of a run add up to;
// one of v_max per ramp (seconds) would be each speed-up's own, and would cost every real stop what
// it tells of the axial accelerometer bias (the outside runs without depth drifted 22.7 -> 27.2 %
// of MD on average with 10 s, 24.4 % with 100 s).
constexpr double kSpeedChangeS = 120;

}  // namespace

void UnseenMotion::reset(const NavigatorConfig& config) {
  config_ = config;
  drilling_tool_ = false;
  unmeasured_ = false;
  notice_given_ = false;
  since_ = 0;
  in_stop_ = false;
  last_depth_t_.reset();
  warning_ = format("along-hole motion not measured: position sigma grows at %.0f m/h through stops; give pipe_joint_m "
                    "or pipe_tally_m", config_.max_rop * 3600.0);
  notices_.clear();
}

void UnseenMotion::at_alignment(double t, bool drilling_tool) {
  drilling_tool_ = drilling_tool;
  // The alignment's stop goes on after the alignment, and the tool may start to slide in it unseen.
  in_stop_ = true;
  since_ = t;
}

UnseenMotionNoise UnseenMotion::at_epoch(const Eigen::Vector3d& axis, const StillnessState& still, double t,
                                         double dt) {
  UnseenMotionNoise noise;
  const double v_max = config_.max_rop;
  const bool measured = !config_.pipe_tally_m.empty() || (last_depth_t_ && t - *last_depth_t_ <= kHeldDepthAgeS);
  unmeasured_ = drilling_tool_ && !measured && v_max > 0;
  if (!still.still) {
    in_stop_ = false;
    return noise;
  }
  if (!in_stop_) {
    in_stop_ = true;
    since_ = t - dt;
  }
  if (!unmeasured_ || !(dt > 0)) return noise;
  // A stop that is a slide: the speed the zero-velocity updates hold at zero may be up to v_max.
  // Its speed-up, unseen, the updates took for a tilt and an accelerometer bias: along the axis
  // the velocity changes for real, by v_max once per kSpeedChangeS on average (a random walk of
  // that rate). The position and the path length have gone up to v_max times the stop's duration:
  // the same unseen speed all along, so that part grows linearly, not as a random walk.
  noise.velocity = (v_max * v_max / kSpeedChangeS * dt) * axis * axis.transpose();
  const double tau = t - since_, before = std::max(0.0, tau - dt);
  Eigen::Vector4d j;
  j << axis, 1.0;
  noise.displacement = v_max * std::sqrt(tau * tau - before * before) * j;
  if (!notice_given_) {
    notice_given_ = true;
    const std::string why = last_depth_t_ ? "depth reports stopped and there is no pipe tally" : "no measured depth and no pipe tally";
    notices_.push_back(why + ": a slide that starts smoothly and runs straight looks still to the sensors, so through "
                             "every stop the position's sigma grows at max_rop_m_per_h (" + format("%.0f m/h", v_max * 3600.0) +
                       ") and the attitude's allows for the speed-up a stop may hide. The remedy is the pipe tally "
                       "(pipe_joint_m or pipe_tally_m), or a depth feed");
  }
  return noise;
}

std::vector<std::string> UnseenMotion::take_notices() { return std::exchange(notices_, {}); }

}  // namespace plumb::strapdown
