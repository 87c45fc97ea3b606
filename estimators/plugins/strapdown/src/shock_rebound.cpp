#include "plumb/strapdown/shock_rebound.hpp"

namespace plumb::strapdown {

void ShockRebound::start(const NavState& before) {
  open_ = true;
  quiet_ = 0;
  p0_ = before.p;
}

bool ShockRebound::ends(const InputReading& in) {
  if (!open_) return false;
  quiet_ = (in.clipped & 7u) != 0 ? 0 : quiet_ + 1;
  return quiet_ >= kQuietReadings;
}

// Across the axis the tool is where it was before the shock, and still (its vibration's velocity
// is centimetres per second, mean zero); along the axis the shock changed nothing either way the
// readings could not show, and the depth sees it.
ShockRebound::Shift ShockRebound::end(const NavState& after, const Eigen::Vector3d& axis_n) {
  open_ = false;
  const auto across = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return x - axis_n * axis_n.dot(x); };
  return Shift{-across(after.v), -across(after.p - p0_)};
}

}  // namespace plumb::strapdown
