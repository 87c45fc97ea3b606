#include "plumb/strapdown/smoother.hpp"

namespace plumb::strapdown {

void RtsSmoother::store(const StateMatrix& phi, double dt, const ProcessNoise& noise,
                        const Eigen::Matrix3d& velocity_noise, const Eigen::Vector4d& displacement_noise,
                        const Eigen::Matrix<double, 6, 1>& turn_noise,
                        const StateVector& correction, const NavState& state,
                        const Eigen::Vector3d& gyro_bias, const Eigen::Vector3d& accel_bias, const StateMatrix& p) {
  Epoch e;
  e.dt = dt;
  e.noise = noise;
  for (int r = 0, j = 0; r < 3; ++r) {
    for (int c = r; c < 3; ++c) e.velocity_noise[j++] = velocity_noise(r, c);
  }
  Eigen::Map<Eigen::Vector4d>(e.displacement_noise) = displacement_noise;
  Eigen::Map<Eigen::Matrix<double, 6, 1>>(e.turn_noise) = turn_noise;
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
  Eigen::Matrix3d velocity;
  for (int r = 0, j = 0; r < 3; ++r) {
    for (int c = r; c < 3; ++c, ++j) velocity(r, c) = velocity(c, r) = next.velocity_noise[j];
  }
  add_noise(pred, velocity, Eigen::Map<const Eigen::Vector4d>(next.displacement_noise),
            Eigen::Map<const Eigen::Matrix<double, 6, 1>>(next.turn_noise));
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
