#include "plumb/strapdown/mechanization.hpp"

#include <algorithm>
#include <cmath>

namespace plumb::strapdown {

Mechanization::Mechanization(const Eigen::Vector3d& w_ie_n, double g) : w_ie_(w_ie_n), g_n_(0.0, 0.0, g) {}

// dq/dt for C_b^n: C' = C [w_ib x] - [w_ie x] C, i.e. q' = q (0, w_ib) / 2 - (0, w_ie) q / 2.
// Quaternions as (w, x, y, z) in a Vector4d so that Runge-Kutta stages add as vectors.
// With q = (s, v): q (0, w) = (-v.w, s w + v x w) and (0, e) q = (-e.v, s e + e x v), so
// 2 q' = (v.(e - w), s (w - e) + v x w + v x e): two cross products, no quaternion objects.
Eigen::Vector4d Mechanization::attitude_rate(const Eigen::Vector4d& q, const Eigen::Vector3d& w) const {
  const Eigen::Vector3d v = q.tail<3>();
  const Eigen::Vector3d vector = q[0] * (w - w_ie_) + v.cross(w + w_ie_);
  Eigen::Vector4d rate;
  rate << 0.5 * v.dot(w_ie_ - w), 0.5 * vector;
  return rate;
}

void Mechanization::step(NavState& state, const ImuReading& a, const ImuReading& b, StepIntegrals* integrals,
                         const ImuReading* before) const {
  const double dt = b.t - a.t;
  if (!(dt > 0)) return;
  // Lagrange parabola through (before, a, b), or the line through (a, b); u in [0, 1] across the step.
  // Only between evenly spaced readings: across a gap the parabola would extrapolate the noise's
  // curvature (its coefficients stay within [-1/8, 1] only while the spacings are alike).
  const double previous_dt = before != nullptr ? a.t - before->t : 0.0;
  const bool parabola = before != nullptr && previous_dt > 0.5 * dt && previous_dt < 2.0 * dt;
  // The parabola's Lagrange weights in s = t - a.t: l0 = s (s - dt) / d0, l1 = (s + p)(s - dt) / d1,
  // l2 = (s + p) s / d2 (p = previous_dt), the denominators once per step.
  const double inv_d0 = parabola ? 1.0 / (previous_dt * (previous_dt + dt)) : 0.0;
  const double inv_d1 = parabola ? -1.0 / (previous_dt * dt) : 0.0;
  const double inv_d2 = parabola ? 1.0 / ((previous_dt + dt) * dt) : 0.0;
  auto rate = [&](double u) -> Eigen::Vector3d {
    if (!parabola) return a.w + (b.w - a.w) * u;
    const double s = u * dt;
    return (s * (s - dt) * inv_d0) * before->w + ((s + previous_dt) * (s - dt) * inv_d1) * a.w +
           ((s + previous_dt) * s * inv_d2) * b.w;
  };
  const Eigen::Matrix3d c0 = state.q.toRotationMatrix();
  const Eigen::Vector3d v0 = state.v;

  // Attitude: RK4 with w(t) linear between the readings, in as many sub-steps as the turn needs.
  const double turn = std::max(a.w.norm(), b.w.norm()) * dt;
  const int substeps = std::clamp(static_cast<int>(std::ceil(turn / kMaxSubstepAngle)), 1, 4096);
  const double h = dt / substeps;
  Eigen::Vector4d q(state.q.w(), state.q.x(), state.q.y(), state.q.z());
  for (int i = 0; i < substeps; ++i) {
    const double u0 = static_cast<double>(i) / substeps, u1 = static_cast<double>(i + 1) / substeps;
    const Eigen::Vector3d w0 = rate(u0);
    const Eigen::Vector3d w1 = rate(u1);
    const Eigen::Vector3d wm = rate(0.5 * (u0 + u1));
    const Eigen::Vector4d k1 = attitude_rate(q, w0);
    const Eigen::Vector4d k2 = attitude_rate(q + 0.5 * h * k1, wm);
    const Eigen::Vector4d k3 = attitude_rate(q + 0.5 * h * k2, wm);
    const Eigen::Vector4d k4 = attitude_rate(q + h * k3, w1);
    q += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  q.normalize();
  state.q = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  const Eigen::Matrix3d c1 = state.q.toRotationMatrix();

  // Velocity: Heun (2nd order) on v' = C f - 2 w_ie x v + g.
  const Eigen::Vector3d fn0 = c0 * a.f, fn1 = c1 * b.f;
  const Eigen::Vector3d acc0 = fn0 - 2.0 * w_ie_.cross(v0) + g_n_;
  const Eigen::Vector3d v_pred = v0 + dt * acc0;
  const Eigen::Vector3d acc1 = fn1 - 2.0 * w_ie_.cross(v_pred) + g_n_;
  state.v = v0 + 0.5 * dt * (acc0 + acc1);

  // Position and along-hole distance: Euler (1st order), see the header.
  const Eigen::Vector3d axis0 = c0.col(2);
  state.p += v0 * dt;
  state.s += axis0.dot(v0) * dt;

  if (integrals != nullptr) {
    integrals->dt += dt;
    integrals->c_bn += 0.5 * dt * (c0 + c1);
    integrals->f_n += 0.5 * dt * (fn0 + fn1);
    integrals->axis_n += 0.5 * dt * (axis0 + c1.col(2));
    integrals->axis_cross_v += 0.5 * dt * (axis0.cross(v0) + c1.col(2).cross(state.v));
  }
}

}  // namespace plumb::strapdown
