// A drilling tool whose axial gyro reads at its range (stick-slip's slip phase past a MEMS gyro's
// range, or the whole rotary segment of a string turning faster than it) turns faster than the gyro
// says, by an amount that over a slip of a second is hundreds of degrees: as process noise alone
// (sensor_range.hpp) that breaks the filter's linearization. Gravity's part across the axis, which
// the accelerometers see, turns the other way as the tool turns; a phase-locked loop on its angle,
// with its rate held beyond the range (where the truth is), follows the spin through the clipped
// readings: a smooth rate for the mechanization (the lever arm's centripetal term takes it), and
// the loop's phase corrections as turns about the axis after each step. The magnetometers, where
// the tool has them, see the field's part across the axis turn the same way, without the
// vibration: the loop follows that instead. The loop's innovations say how far it can be off: that
// spread is the attitude's noise about the axis while it tracks.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/navigator_config.hpp"

namespace plumb::strapdown {

class ClippedSpin {
 public:
  struct Spin {
    double rate = 0;  // rad/s about the tool axis at the reading, for the mechanization
    double turn = 0;  // rad about the tool axis after the step: what the step's rates did not turn
  };
  void reset(const NavigatorConfig& config);
  // A reading of a drilling tool whose axial gyro is at its range (or held, saturated), dt after
  // prev (whose axial rate is the one integrated); c_bn the tool's attitude at prev, g gravity.
  // None where neither the field's part across the axis nor gravity's is large enough to show the
  // toolface (the axis within 11.5 degrees of both): the clipped readings' noise then stands alone.
  std::optional<Spin> through(const InputReading& in, const InputReading& prev, double dt, const Eigen::Matrix3d& c_bn,
                              double g);
  // What the loop follows now: "magnetometers" or "accelerometers".
  const char* source_name() const { return source_ == 1 ? "magnetometers" : "accelerometers"; }
  // A reading whose axial rate the gyro read: a span of clipped ones has ended.
  void read() { tracking_ = false; }
  // The attitude's variance about the tool axis (rad^2) the loop's tracking adds to this epoch.
  double take_variance();

  // A vector's part across the axis below this fraction of it (the axis within 11.5 degrees of
  // it) shows the toolface too weakly.
  static constexpr double kMinAcrossAxis = 0.2;

 private:
  NavigatorConfig config_;
  bool tracking_ = false;
  int source_ = 0;     // what the loop follows: 0 gravity (the accelerometers), 1 the field
  double phase_ = 0;   // the source's angle across the axis in the tool frame, atan2(y, x), as tracked
  double rate_ = 0;    // the tool's rate about its axis, rad/s
  double innovation2_[2] = {0, 0};  // each source's innovations' mean square, over the last kSpreadMemoryS
  double variance_ = 0;
};

// A gap (samples lost) hides the tool's turn about its axis the same way: the made-up readings
// turn it on the rate's line between the readings either side, which a swinging spin (stick-slip)
// leaves tens of degrees off. The field's part across the axis before (prev) and after (in) the gap,
// against where the mechanization's turn across it (c_before to c_after, tool to navigation frame)
// puts the field, says what is left: the turn to add about the axis, modulo a whole turn (all an
// attitude needs). None without the field across the axis at both ends: unlike a loop that must
// follow every reading, one angle before and one after are weighed against their own noise
// (StreamFaults::axial_turn_seen), so a part across the axis of a twentieth of the field will do
// (the axis within 3 degrees of the field line: 2.3 uT of 46, tens of times the noise of a tool's
// magnetometers).
std::optional<double> unseen_turn_across_gap(const InputReading& prev, const InputReading& in,
                                             const Eigen::Matrix3d& c_before, const Eigen::Matrix3d& c_after);

}  // namespace plumb::strapdown
