#include "plumb/strapdown/error_state_filter.hpp"

#include "plumb/strapdown/rotation.hpp"

namespace plumb::strapdown {

using namespace index;

StateMatrix ErrorStateFilter::transition(const StepIntegrals& in, const Eigen::Vector3d& w_ie,
                                         const Eigen::Vector3d& gravity_coupling) {
  StateMatrix phi = StateMatrix::Identity();
  const double dt = in.dt;
  if (!(dt > 0)) return phi;
  const Eigen::Matrix3d c = in.c_bn / dt;
  StateMatrix f = StateMatrix::Zero();
  f.block<3, 3>(kAtt, kAtt) = -skew(w_ie);
  f.block<3, 3>(kAtt, kGyroBias) = -c;
  f.block<3, 3>(kVel, kAtt) = -skew(in.f_n / dt);
  f.block<3, 3>(kVel, kVel) = -2.0 * skew(w_ie);
  f.block<3, 3>(kVel, kAccelBias) = -c;
  f.block<1, 3>(kVel + 2, kAccelBias) += gravity_coupling.transpose();
  f.block<3, 3>(kPos, kVel) = Eigen::Matrix3d::Identity();
  f.block<1, 3>(kDistance, kAtt) = (in.axis_cross_v / dt).transpose();
  f.block<1, 3>(kDistance, kVel) = (in.axis_n / dt).transpose();
  const StateMatrix fdt = f * dt;
  // F's columns 6-8 and 15 are zero, and its rows 6-15 hold only the identity block of dp' = dv
  // and the distance row: (F dt)^2 = (F dt)(:, 0:5) (F dt)(0:5, :), a sixth of the inner products.
  phi += fdt;
  phi.noalias() += 0.5 * fdt.leftCols<6>().lazyProduct(fdt.topRows<6>());
  return phi;
}

namespace {

// The white noises over dt. They enter through C (a rotation), and are the same on each axis:
// C q I C' = q I, so Q is diagonal.
StateVector white_noise(double dt, const ProcessNoise& n) {
  StateVector q = StateVector::Zero();
  q.segment<3>(kAtt).setConstant(n.gyro_arw * n.gyro_arw * dt);
  q.segment<3>(kVel).setConstant(n.accel_vrw * n.accel_vrw * dt);
  q.segment<3>(kGyroBias).setConstant(n.gyro_bias_walk * n.gyro_bias_walk * dt);
  q.segment<3>(kAccelBias).setConstant(n.accel_bias_walk * n.accel_bias_walk * dt);
  return q;
}

}  // namespace

StateMatrix ErrorStateFilter::sandwich(const StateMatrix& phi, const StateMatrix& m) {
  StateMatrix pm = m;
  pm.topRows<9>().noalias() = phi.topRows<9>().lazyProduct(m);
  pm.row(kDistance).noalias() = phi.row(kDistance).lazyProduct(m);
  StateMatrix out = pm;
  out.leftCols<9>().noalias() = pm.lazyProduct(phi.topRows<9>().transpose());
  out.col(kDistance).noalias() = pm.lazyProduct(phi.row(kDistance).transpose());
  return out;
}

StateMatrix ErrorStateFilter::predicted_covariance(const StateMatrix& phi, const StateMatrix& p, double dt,
                                                   const ProcessNoise& noise) {
  const StateVector half_q = 0.5 * white_noise(dt, noise);
  StateMatrix m = p;
  m.diagonal() += half_q;
  StateMatrix out = sandwich(phi, m);
  out.diagonal() += half_q;
  return out;
}

void ErrorStateFilter::predict(const StateMatrix& phi, double dt, const ProcessNoise& noise) {
  p_ = predicted_covariance(phi, p_, dt, noise);
  symmetrize();
}

void feed_back(const StateVector& dx, NavState& state, Eigen::Vector3d& gyro_bias, Eigen::Vector3d& accel_bias) {
  // C(true) = (I + [phi x])^-1 C(est) = exp(-[phi x]) C(est): a rotation on the navigation side.
  state.q = (quaternion_from_rotation_vector(-dx.segment<3>(kAtt)) * state.q).normalized();
  state.v -= dx.segment<3>(kVel);
  state.p -= dx.segment<3>(kPos);
  gyro_bias -= dx.segment<3>(kGyroBias);
  accel_bias -= dx.segment<3>(kAccelBias);
  state.s -= dx[kDistance];
}

}  // namespace plumb::strapdown
