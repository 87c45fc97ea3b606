// The true state of the foot at any instant, in closed form: standing on a footprint, or in a swing
// between two (walk.hpp gives the profiles); the angular rate from the angles' rates.
#include <algorithm>
#include <cmath>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/drilling.hpp"  // rate_nb
#include "walk_detail.hpp"

namespace plumb::sim {
namespace {

// The foot's heading, pitch and roll as the tool's angles for the mounting of walk.hpp.
void set_attitude(WalkState& st, double heading, double pitch, double roll, double heading_rate, double pitch_rate,
                  double roll_rate) {
  st.inclination = 0.5 * kPi + pitch;
  st.azimuth = heading;
  st.toolface = roll;
  st.inclination_rate = pitch_rate;
  st.azimuth_rate = heading_rate;
  st.toolface_rate = roll_rate;
  st.c_nb = c_nb(st.inclination, st.azimuth, st.toolface);
  st.w_nb = rate_nb(st.inclination, st.toolface, pitch_rate, heading_rate, roll_rate);
}

}  // namespace

bool WalkPath::still_at(double t) const {
  const auto it = std::upper_bound(swings_.begin(), swings_.end(), t,
                                   [](double x, const Swing& s) { return x < s.t0; });
  return it == swings_.begin() || t >= std::prev(it)->t1;
}

WalkState WalkPath::at(double t) const {
  WalkState st;
  st.t = t;
  const auto it = std::upper_bound(swings_.begin(), swings_.end(), t,
                                   [](double x, const Swing& s) { return x < s.t0; });
  if (it == swings_.begin()) {
    const Footprint& f = footprints_.front();
    st.position = f.position;
    set_attitude(st, f.heading, 0, 0, 0, 0, 0);
    return st;
  }
  const Swing& sw = *std::prev(it);
  st.stride = static_cast<std::size_t>(it - swings_.begin());
  if (t >= sw.t1) {
    const Footprint& f = footprints_[sw.from + 1];
    st.position = f.position;
    set_attitude(st, f.heading, 0, 0, 0, 0, 0);
    return st;
  }
  st.still = false;
  const Footprint& a = footprints_[sw.from];
  const Footprint& b = footprints_[sw.from + 1];
  const double d = sw.t1 - sw.t0;
  const double tau = (t - sw.t0) / d;
  const detail::SwingProfile s = detail::swing_step(tau);
  const detail::SwingProfile lift = detail::swing_bump(tau);
  const detail::SwingProfile wave = detail::swing_wave(tau);
  const Eigen::Vector3d span = b.position - a.position;
  const Eigen::Vector3d up(0.0, 0.0, -clearance_);
  st.position = a.position + s.value * span + lift.value * up;
  st.velocity = (s.rate * span + lift.rate * up) / d;
  st.acceleration = (s.rate_dot * span + lift.rate_dot * up) / (d * d);
  const double turn = b.heading - a.heading;
  set_attitude(st, a.heading + turn * s.value, -pitch_ * wave.value, roll_ * lift.value, turn * s.rate / d,
               -pitch_ * wave.rate / d, roll_ * lift.rate / d);
  return st;
}

}  // namespace plumb::sim
