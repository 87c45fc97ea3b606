// The true state of the drilling run at any instant, in closed form from the compiled phases:
// depth and speed from the raised-cosine drive, attitude linear in depth, the rates by the chain
// rule, the position by the exact integral along the hole.
#include <algorithm>

#include "drilling_detail.hpp"
#include "plumb/core/attitude.hpp"
#include "plumb/sim/drilling.hpp"

namespace plumb::sim {

Eigen::Vector3d rate_nb(double inc, double tf, double inc_rate, double azi_rate, double tf_rate) {
  // C_n^b = R3(T) R2(I) R3(A): each frame rotation adds its rate about its own axis, carried into
  // the tool frame by the rotations that follow it.
  const Eigen::Matrix3d r3t = rot3(tf);
  return Eigen::Vector3d(0.0, 0.0, tf_rate) + r3t * Eigen::Vector3d(0.0, inc_rate, 0.0) +
         r3t * rot2(inc) * Eigen::Vector3d(0.0, 0.0, azi_rate);
}

DrillingState DrillingTrajectory::at(double t) const {
  DrillingState st;
  st.t = t;
  st.phase = phase_at(t);
  const Phase& ph = phases_[st.phase];
  st.still = !ph.moving || t >= duration_s() || t < 0;

  double along = 0;  // distance drilled in this phase, m
  double speed = 0, accel = 0;
  double slip_angle = 0, slip_rate = 0;  // stick-slip: drive x slip sin(w tau) / w, and its rate
  if (ph.moving) {
    const double tau = std::clamp(t, ph.t0, ph.t1) - ph.t0;
    const detail::Drive d = detail::raised_cosine_drive(tau, ph.t1 - ph.t0, ph.ramp);
    along = ph.rop * d.along;
    speed = ph.rop * d.rate;
    accel = ph.rop * d.rate_dot;
    st.drive = d.rate;
    if (ph.slip > 0) {
      const double s = std::sin(ph.slip_w * tau) / ph.slip_w, c = std::cos(ph.slip_w * tau);
      slip_angle = ph.slip * d.rate * s;
      slip_rate = ph.slip * (d.rate_dot * s + d.rate * c);
    }
  }
  st.depth_m = ph.s0 + along;
  st.speed_mps = speed;
  st.inclination = ph.inc0 + ph.build * along;
  st.azimuth = ph.azi0 + ph.turn * along;
  st.toolface = ph.tf0 + ph.spin * along + slip_angle;
  st.toolface_rate = ph.spin * speed + slip_rate;
  st.c_nb = c_nb(st.inclination, st.azimuth, st.toolface);
  st.w_nb = rate_nb(st.inclination, st.toolface, ph.build * speed, ph.turn * speed, st.toolface_rate);

  const double si = std::sin(st.inclination), ci = std::cos(st.inclination);
  const double sa = std::sin(st.azimuth), ca = std::cos(st.azimuth);
  const Eigen::Vector3d u(si * ca, si * sa, ci);
  const Eigen::Vector3d du_di(ci * ca, ci * sa, -si);
  const Eigen::Vector3d du_da(-si * sa, si * ca, 0.0);
  st.velocity = speed * u;
  // d(s' u)/dt = s'' u + s'^2 (build du/dI + turn du/dA).
  st.acceleration = accel * u + speed * speed * (ph.build * du_di + ph.turn * du_da);
  st.position = ph.p0 + detail::along_hole(ph.inc0, ph.azi0, ph.build, ph.turn, along);
  return st;
}

}  // namespace plumb::sim
