#include "plumb/strapdown/mechanization.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "plumb/strapdown/rotation.hpp"

namespace plumb::strapdown {

namespace {

// The two Gauss-Legendre points of a step, as fractions of it.
constexpr double kGauss1 = 0.5 - std::numbers::sqrt3 / 6.0;
constexpr double kGauss2 = 0.5 + std::numbers::sqrt3 / 6.0;
constexpr double kConing = std::numbers::sqrt3 / 12.0;

// C~ G(f) (gyro_g_matrix) from C~ f: G(f)'s columns are (f_x, f_y, 0) and e_z x f, and a rotation
// turns a cross product into the cross product of the turned vectors.
inline Eigen::Matrix<double, 3, 2> tool_gyro_g(const Eigen::Matrix3d& c, const Eigen::Vector3d& f,
                                               const Eigen::Vector3d& cf) {
  Eigen::Matrix<double, 3, 2> m;
  m.col(0) = cf - c.col(2) * f.z();
  m.col(1) = c.col(2).cross(cf);
  return m;
}

}  // namespace

namespace {

// A turn of theta over the interval shortens the part across the rate by sin(theta/2) / (theta/2)
// in the mean; `factor` maps that ratio to the scale wanted (mean to instant, or back).
Eigen::Vector3d scale_across_rate(const Eigen::Vector3d& f, const Eigen::Vector3d& w, double dt,
                                  double (*factor)(double half)) {
  const double theta = w.norm() * dt;
  if (theta < 1e-3) return f;
  const Eigen::Vector3d u = w / w.norm();
  const Eigen::Vector3d along = u * u.dot(f);
  return along + (f - along) * factor(0.5 * theta);
}

}  // namespace

Eigen::Vector3d mean_to_instant(const Eigen::Vector3d& mean_f, const Eigen::Vector3d& w, double dt) {
  return scale_across_rate(mean_f, w, dt, [](double half) { return half / std::sin(half); });
}

Eigen::Vector3d instant_to_mean(const Eigen::Vector3d& instant_f, const Eigen::Vector3d& w, double dt) {
  return scale_across_rate(instant_f, w, dt, [](double half) { return std::sin(half) / half; });
}

Mechanization::Mechanization(const Eigen::Vector3d& w_ie_n, double g) : w_ie_(w_ie_n), g_n_(0.0, 0.0, g) {}

void Mechanization::begin(const NavState& state) {
  start_ = state;
  c0_ = state.q.toRotationMatrix();
  w_b0_ = c0_.transpose() * w_ie_;
  v_b0_ = c0_.transpose() * state.v;
  g_b0_ = c0_.transpose() * g_n_;
  earth_dt_ = 0;
  b_ = Eigen::Quaterniond::Identity();
  c_.setIdentity();
  tau_ = tau_sum_ = 0;
  u_.setZero();
  u_sum_.setZero();
  s_sum_ = 0;
  c_int_.setZero();
  axis_cross_v_int_.setZero();
  spin_int_.setZero();
  gyro_g_int_.setZero();
  lever_int_.setZero();
  unresolved_dv2_ = 0;
  last_lever_.setZero();
  stepped_ = false;
}

void Mechanization::step(const ImuReading& a, const ImuReading& b, const ImuReading* before) {
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
  const Eigen::Vector3d& w_before = parabola ? before->w : a.w;
  auto rate = [&](double u) -> Eigen::Vector3d {
    if (!parabola) return a.w + (b.w - a.w) * u;
    const double s = u * dt;
    return (s * (s - dt) * inv_d0) * w_before + ((s + previous_dt) * (s - dt) * inv_d1) * a.w +
           ((s + previous_dt) * s * inv_d2) * b.w;
  };

  // Attitude: the Magnus step (rates at the Gauss points, the cross product the coning correction)
  // in as many sub-steps as the turn needs; the earth's rotation of b0 on the other side.
  const double turn2 = std::max(a.w.squaredNorm(), b.w.squaredNorm()) * dt * dt;
  Eigen::Quaterniond d;
  if (turn2 <= kMaxSubstepAngle * kMaxSubstepAngle) {
    const Eigen::Vector3d w1 = rate(kGauss1), w2 = rate(kGauss2);
    d = quaternion_from_rotation_vector(0.5 * dt * (w1 + w2) + (kConing * dt * dt) * w1.cross(w2));
  } else {
    const int substeps = std::clamp(static_cast<int>(std::ceil(std::sqrt(turn2) / kMaxSubstepAngle)), 1, 4096);
    const double h = dt / substeps;
    d = Eigen::Quaterniond::Identity();
    for (int i = 0; i < substeps; ++i) {
      const Eigen::Vector3d w1 = rate((i + kGauss1) / substeps);
      const Eigen::Vector3d w2 = rate((i + kGauss2) / substeps);
      d = d * quaternion_from_rotation_vector(0.5 * h * (w1 + w2) + (kConing * h * h) * w1.cross(w2));
    }
  }
  // The earth's turn of b0 over dt, kept while the steps are alike (it changes only with dt and b0).
  if (dt != earth_dt_) {
    earth_dt_ = dt;
    earth_turn_ = quaternion_from_rotation_vector(-dt * w_b0_);
  }
  b_ = earth_turn_ * b_ * d;
  const Eigen::Matrix3d c1 = b_.toRotationMatrix();

  // At reading a: the velocity in b0 (less Coriolis, which the full update adds), and the
  // first-order sums of position and distance.
  const Eigen::Vector3d va = v_b0_ + u_ + g_b0_ * tau_;
  // Before the first step since begin() C~ is the identity.
  const Eigen::Vector3d& fa = stepped_ ? last_f_ : a.f;
  const Eigen::Vector3d axa = stepped_ ? last_axis_cross_v_ : Eigen::Vector3d(c_.col(2).cross(va));
  u_sum_ += dt * u_;
  tau_sum_ += dt * tau_;
  s_sum_ += dt * c_.col(2).dot(va);

  // Velocity: the trapezoid of C~ f (Heun's sum of the specific force); gravity at the full update.
  const Eigen::Vector3d fb = c1.lazyProduct(b.f);
  u_ += 0.5 * dt * (fa + fb);
  if (unresolved_vibration_) unresolved_dv2_ += unresolved_velocity_variance(turn2, dt, fb - fa, c1.col(2));
  tau_ += dt;
  const Eigen::Vector3d axb = c1.col(2).cross(v_b0_ + u_ + g_b0_ * tau_);

  // The filter's integrals, by the trapezoid.
  c_int_ += (0.5 * dt) * (c_ + c1);
  axis_cross_v_int_ += 0.5 * dt * (axa + axb);
  spin_int_ += (0.5 * dt) * (a.w.z() * c_ + b.w.z() * c1);
  const Eigen::Matrix<double, 3, 2> ga =
      stepped_ && a.f == last_raw_f_ ? last_gyro_g_ : tool_gyro_g(c_, a.f, c_.lazyProduct(a.f));
  const Eigen::Matrix<double, 3, 2> gb = tool_gyro_g(c1, b.f, fb);
  gyro_g_int_ += (0.5 * dt) * (ga + gb);
  if (lever_model_) {
    // C~ L(w) at b is the next step's value at a.
    const auto turning = [](const Eigen::Vector3d& w) { return w.squaredNorm() > kTurningRate2; };
    const Eigen::Matrix<double, 3, 2> lb = turning(b.w) ? Eigen::Matrix<double, 3, 2>(c1.lazyProduct(centripetal_matrix(b.w)))
                                                        : Eigen::Matrix<double, 3, 2>::Zero();
    const Eigen::Matrix<double, 3, 2> la =
        stepped_ ? last_lever_
                 : (turning(a.w) ? Eigen::Matrix<double, 3, 2>(c_.lazyProduct(centripetal_matrix(a.w)))
                                 : Eigen::Matrix<double, 3, 2>::Zero());
    if (turning(a.w) || turning(b.w)) lever_int_ += (0.5 * dt) * (la + lb);
    last_lever_ = lb;
  }
  c_ = c1;
  last_f_ = fb;
  last_axis_cross_v_ = axb;
  last_gyro_g_ = gb;
  last_raw_f_ = b.f;
  stepped_ = true;
}

void Mechanization::turn_about_axis(double angle) {
  if (!stepped_ || angle == 0) return;
  const Eigen::Matrix3d before = c_;
  b_ = (b_ * Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()))).normalized();
  c_ = b_.toRotationMatrix();
  // The next step's values at its first reading: the same reading seen from the turned attitude.
  const Eigen::Matrix3d change = c_ * before.transpose();
  last_f_ = change * last_f_;
  last_lever_ = change * last_lever_;
  last_gyro_g_ = tool_gyro_g(c_, last_raw_f_, c_.lazyProduct(last_raw_f_));
}

void Mechanization::shift(const Eigen::Vector3d& dv_n, const Eigen::Vector3d& dp_n) {
  if (!stepped_) return;
  u_.noalias() += c0_.transpose() * dv_n;
  u_sum_.noalias() += c0_.transpose() * dp_n;
  last_axis_cross_v_ = c_.col(2).cross(v_b0_ + u_ + g_b0_ * tau_);
}

NavState Mechanization::state() const {
  NavState x = start_;
  if (!stepped_) return x;
  x.q = (start_.q * b_).normalized();
  const double t = tau_;
  const Eigen::Vector3d v = start_.v + c0_ * u_ + g_n_ * t;
  const Eigen::Vector3d dp = start_.v * t + c0_ * u_sum_ + g_n_ * tau_sum_;
  // Coriolis, -2 w_ie x v, over the steps: the velocity changes by -2 w_ie x (the position's change),
  // the position by about half that times t (both 1e-4 of the change, or less, at a 20 Hz epoch).
  x.v = v - 2.0 * w_ie_.cross(dp);
  x.p = start_.p + dp - t * w_ie_.cross(dp);
  x.s = start_.s + s_sum_;
  return x;
}

void Mechanization::finish(NavState& state, StepIntegrals* integrals) {
  state = this->state();
  if (integrals != nullptr && stepped_) {
    const Eigen::Matrix3d c_bn = c0_ * c_int_;
    integrals->dt += tau_;
    integrals->c_bn += c_bn;
    integrals->f_n += c0_ * u_;
    integrals->axis_n += c_bn.col(2);
    integrals->axis_cross_v += c0_ * axis_cross_v_int_;
    integrals->spin_frame += c0_ * spin_int_;
    integrals->c_gyro_g += c0_ * gyro_g_int_;
    if (lever_model_) integrals->c_lever += c0_ * lever_int_;
    integrals->unresolved_dv2 += unresolved_dv2_;
  }
}

void Mechanization::step(NavState& state, const ImuReading& a, const ImuReading& b, StepIntegrals* integrals,
                         const ImuReading* before) {
  begin(state);
  step(a, b, before);
  finish(state, integrals);
}

}  // namespace plumb::strapdown
