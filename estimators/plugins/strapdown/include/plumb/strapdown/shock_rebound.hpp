// A shock of tens of g on a drilling tool is the string striking the hole's wall and coming back:
// its velocity across the axis returns and its displacement is a few millimetres (the hole's
// clearance). Clipped at the accelerometers' range, the readings lose the peak beyond it, and the
// mechanization comes out of the shock with a velocity across the axis that the tool does not have,
// which the lateral-velocity updates take out only over the next epochs: centimetres of position
// per shock. This part marks a burst of clipped readings and, a few readings after the last one,
// says how to take out the velocity across the axis the burst left and the displacement across
// the axis it made.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "plumb/strapdown/mechanization.hpp"
#include "plumb/strapdown/navigator_common.hpp"

namespace plumb::strapdown {

class ShockRebound {
 public:
  struct Shift {
    Eigen::Vector3d dv = Eigen::Vector3d::Zero(), dp = Eigen::Vector3d::Zero();  // navigation frame
  };
  void reset() { *this = ShockRebound(); }
  // Whether a reading starts a burst (an accelerometer clipped while none is open): the caller then
  // hands over the state before its step.
  bool starts(const InputReading& in) const { return !open_ && (in.clipped & 7u) != 0; }
  void start(const NavState& before);
  // Whether the open burst ends with this reading (kQuietReadings unclipped since the last clipped
  // one); the caller then hands over the state after its step and the tool's axis.
  bool ends(const InputReading& in);
  bool open() const { return open_; }
  Shift end(const NavState& after, const Eigen::Vector3d& axis_n);

  // A rebounding shock's readings beyond the range come back within a few readings at 100 Hz.
  static constexpr int kQuietReadings = 3;

 private:
  bool open_ = false;
  int quiet_ = 0;
  Eigen::Vector3d p0_ = Eigen::Vector3d::Zero();
};

}  // namespace plumb::strapdown
