#include "plumb/strapdown/smoother.hpp"

namespace plumb::strapdown {

namespace {

void pack_symmetric(const Eigen::Matrix3d& m, double* upper) {
  for (int r = 0, j = 0; r < 3; ++r) {
    for (int c = r; c < 3; ++c) upper[j++] = m(r, c);
  }
}

Eigen::Matrix3d unpack_symmetric(const double* upper) {
  Eigen::Matrix3d m;
  for (int r = 0, j = 0; r < 3; ++r) {
    for (int c = r; c < 3; ++c, ++j) m(r, c) = m(c, r) = upper[j];
  }
  return m;
}

}  // namespace

void RtsSmoother::store(const StateMatrix& phi, double dt, const ProcessNoise& noise, const UnseenMotionNoise& extra,
                        const StateVector& correction, const NavState& state,
                        const Eigen::Vector3d& gyro_bias, const Eigen::Vector3d& accel_bias, const StateMatrix& p) {
  Epoch e;
  e.dt = dt;
  e.noise = noise;
  pack_symmetric(extra.velocity, e.velocity_noise);
  pack_symmetric(extra.attitude, e.attitude_noise);
  Eigen::Map<Eigen::Vector4d>(e.displacement_noise) = extra.displacement;
  Eigen::Map<Eigen::Matrix<double, 6, 1>>(e.turn_noise) = extra.turn;
  std::size_t i = 0;
  for (int r = 0; r < kStates; ++r) {
    for (int c = r; c < kStates; ++c) e.p_upper[i++] = p(r, c);
  }
  Eigen::Map<StateMatrix>(e.phi) = phi;
  Eigen::Map<StateVector>(e.correction) = correction;
  e.q[0] = state.q.w();
  e.q[1] = state.q.x();
  e.q[2] = state.q.y();
  e.q[3] = state.q.z();
  for (int k = 0; k < 3; ++k) {
    e.v[k] = state.v[k];
    e.p[k] = state.p[k];
    e.bg[k] = gyro_bias[k];
    e.ba[k] = accel_bias[k];
  }
  e.s = state.s;
  epochs_.push_back(e);
}

StateMatrix RtsSmoother::covariance(const Epoch& e) const {
  StateMatrix p;
  std::size_t i = 0;
  for (int r = 0; r < kStates; ++r) {
    for (int c = r; c < kStates; ++c) p(r, c) = p(c, r) = e.p_upper[i++];
  }
  return p;
}

StateMatrix RtsSmoother::predicted(const Epoch& next, const StateMatrix& phi, const StateMatrix& pk) {
  StateMatrix pred = ErrorStateFilter::predicted_covariance(phi, pk, next.dt, next.noise);
  UnseenMotionNoise extra;
  extra.velocity = unpack_symmetric(next.velocity_noise);
  extra.attitude = unpack_symmetric(next.attitude_noise);
  extra.displacement = Eigen::Map<const Eigen::Vector4d>(next.displacement_noise);
  extra.turn = Eigen::Map<const Eigen::Matrix<double, 6, 1>>(next.turn_noise);
  add_noise(pred, extra);
  return pred;
}

SmoothedEpoch RtsSmoother::whole(const Epoch& e) const {
  SmoothedEpoch out;
  out.state.q = Eigen::Quaterniond(e.q[0], e.q[1], e.q[2], e.q[3]);
  out.state.v = Eigen::Vector3d(e.v);
  out.state.p = Eigen::Vector3d(e.p);
  out.state.s = e.s;
  out.gyro_bias = Eigen::Vector3d(e.bg);
  out.accel_bias = Eigen::Vector3d(e.ba);
  out.p = covariance(e);
  return out;
}

}  // namespace plumb::strapdown
