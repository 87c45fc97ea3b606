#include "plumb/strapdown/error_state_filter.hpp"

#include <array>
#include <utility>

#include "plumb/strapdown/rotation.hpp"

namespace plumb::strapdown {

using namespace index;

StateMatrix ErrorStateFilter::dynamics(const StepIntegrals& in, const Eigen::Vector3d& w_ie) {
  StateMatrix f = StateMatrix::Zero();
  const double dt = in.dt;
  if (!(dt > 0)) return f;
  const Eigen::Matrix3d c = in.c_bn / dt;
  f.block<3, 3>(kAtt, kAtt) = -skew(w_ie);
  f.block<3, 3>(kAtt, kGyroBias) = -c;
  f.block<3, 3>(kVel, kAtt) = -skew(in.f_n / dt);
  f.block<3, 3>(kVel, kVel) = -2.0 * skew(w_ie);
  f.block<3, 3>(kVel, kAccelBias) = -c;
  f.block<3, 3>(kPos, kVel) = Eigen::Matrix3d::Identity();
  f.block<1, 3>(kDistance, kAtt) = (in.axis_cross_v / dt).transpose();
  f.block<1, 3>(kDistance, kVel) = (in.axis_n / dt).transpose();
  f(kVel + 2, kGravity) = 1.0;
  f.block<3, 2>(kVel, kLever) = -in.c_lever / dt;
  f.block<3, 3>(kAtt, kGyroSpin) = -in.spin_frame / dt;
  f.block<3, 2>(kAtt, kGyroG) = -in.c_gyro_g / dt;
  return f;
}

StateMatrix ErrorStateFilter::transition(const StepIntegrals& in, const Eigen::Vector3d& w_ie) {
  // (Zeros and a diagonal of ones: Eigen writes an identity one coefficient at a time.)
  StateMatrix phi = StateMatrix::Zero();
  phi.diagonal().setOnes();
  const double dt = in.dt;
  if (!(dt > 0)) return phi;
  // The non-zero blocks of A = F dt (dynamics()): F's columns 6-8 and 15 are zero and its bias and
  // gravity rows too, so A^2 takes only products through the attitude and velocity blocks: twelve 3 x 3 products
  // instead of a 16 x 6 x 16 one, and phi = I + A + A^2 / 2 is written block by block.
  const Eigen::Matrix3d aaa = -dt * skew(w_ie), aag = -in.c_bn;
  const Eigen::Matrix3d ava = -skew(in.f_n), avv = 2.0 * aaa;
  const Eigen::Matrix3d& avb = aag;
  const Eigen::RowVector3d ada = in.axis_cross_v.transpose(), adv = in.axis_n.transpose();
  const Eigen::Matrix3d vva = ava * aaa + avv * ava, vvb = avv * avb;
  const Eigen::Matrix3d vvv = avv * avv;
  phi.block<3, 3>(kAtt, kAtt) += aaa + 0.5 * aaa * aaa;
  phi.block<3, 3>(kAtt, kGyroBias) = aag + 0.5 * aaa * aag;
  phi.block<3, 3>(kVel, kAtt) = ava + 0.5 * vva;
  phi.block<3, 3>(kVel, kVel) += avv + 0.5 * vvv;
  phi.block<3, 3>(kVel, kGyroBias) = 0.5 * ava * aag;
  phi.block<3, 3>(kVel, kAccelBias) = avb + 0.5 * vvb;
  // dp' = dv: the position rows are dt times the velocity rows of A, and of A^2 / 2 for A^2.
  phi.block<3, 3>(kPos, kAtt) = (0.5 * dt) * ava;
  phi.block<3, 3>(kPos, kVel) = dt * (Eigen::Matrix3d::Identity() + 0.5 * avv);
  phi.block<3, 3>(kPos, kAccelBias) = (0.5 * dt) * avb;
  phi.block<1, 3>(kDistance, kAtt) = ada + 0.5 * (ada * aaa + adv * ava);
  phi.block<1, 3>(kDistance, kVel) = adv + 0.5 * adv * avv;
  phi.block<1, 3>(kDistance, kGyroBias) = 0.5 * ada * aag;
  phi.block<1, 3>(kDistance, kAccelBias) = 0.5 * adv * avb;
  // Gravity's column: A's is dt on the down velocity, A^2's is dt times A's down-velocity column.
  phi.block<3, 1>(kVel, kGravity) = dt * (Eigen::Vector3d::UnitZ() + 0.5 * avv.col(2));
  phi(kPos + 2, kGravity) = 0.5 * dt * dt;
  phi(kDistance, kGravity) = 0.5 * dt * adv(2);
  // The lever arm's columns enter through the velocity as the accelerometer bias's do.
  const Eigen::Matrix<double, 3, 2> avl = -in.c_lever;
  phi.block<3, 2>(kVel, kLever) = avl + 0.5 * avv * avl;
  phi.block<3, 2>(kPos, kLever) = (0.5 * dt) * avl;
  phi.block<1, 2>(kDistance, kLever) = 0.5 * adv * avl;
  // The spin columns (misalignment and scale factor) enter through the attitude as the gyro bias's
  // do, weighted by the rate about the tool axis.
  const Eigen::Matrix3d aak = -in.spin_frame;
  phi.block<3, 3>(kAtt, kGyroSpin) = aak + 0.5 * aaa * aak;
  phi.block<3, 3>(kVel, kGyroSpin) = 0.5 * ava * aak;
  phi.block<1, 3>(kDistance, kGyroSpin) = 0.5 * ada * aak;
  const Eigen::Matrix<double, 3, 2> aaq = -in.c_gyro_g;
  phi.block<3, 2>(kAtt, kGyroG) = aaq + 0.5 * aaa * aaq;
  phi.block<3, 2>(kVel, kGyroG) = 0.5 * ava * aaq;
  phi.block<1, 2>(kDistance, kGyroG) = 0.5 * ada * aaq;
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
  // phi's blocks as transition() fills them: rows of attitude (columns: attitude, gyro bias),
  // velocity (attitude, velocity, both biases), position (attitude, velocity, the identity,
  // accelerometer bias) and distance (all but position, 1 on the diagonal), each with its gravity
  // and lever-arm columns; the bias, gravity and lever-arm rows are the identity's. Products by block: 3 x 3 blocks against 3-row strips, about 60 % of the
  // multiply-adds of full rows of phi.
  constexpr int a = kAtt, v = kVel, p = kPos, g = kGyroBias, b = kAccelBias, d = kDistance, n = kGravity, l = kLever,
                k = kGyroSpin, q = kGyroG;
  StateMatrix pm = m;
  pm.middleRows<3>(a).noalias() = phi.block<3, 3>(a, a).lazyProduct(m.middleRows<3>(a)) +
                                  phi.block<3, 3>(a, g).lazyProduct(m.middleRows<3>(g)) +
                                  phi.block<3, 3>(a, k).lazyProduct(m.middleRows<3>(k)) +
                                  phi.block<3, 2>(a, q).lazyProduct(m.middleRows<2>(q));
  pm.middleRows<3>(v).noalias() =
      phi.block<3, 3>(v, a).lazyProduct(m.middleRows<3>(a)) + phi.block<3, 3>(v, v).lazyProduct(m.middleRows<3>(v)) +
      phi.block<3, 3>(v, g).lazyProduct(m.middleRows<3>(g)) + phi.block<3, 3>(v, b).lazyProduct(m.middleRows<3>(b)) +
      phi.block<3, 1>(v, n).lazyProduct(m.row(n)) + phi.block<3, 2>(v, l).lazyProduct(m.middleRows<2>(l)) +
      phi.block<3, 3>(v, k).lazyProduct(m.middleRows<3>(k)) + phi.block<3, 2>(v, q).lazyProduct(m.middleRows<2>(q));
  pm.middleRows<3>(p).noalias() += phi.block<3, 3>(p, a).lazyProduct(m.middleRows<3>(a)) +
                                   phi.block<3, 3>(p, v).lazyProduct(m.middleRows<3>(v)) +
                                   phi.block<3, 3>(p, b).lazyProduct(m.middleRows<3>(b)) +
                                   phi.block<3, 1>(p, n).lazyProduct(m.row(n)) +
                                   phi.block<3, 2>(p, l).lazyProduct(m.middleRows<2>(l));
  pm.row(d).noalias() += phi.block<1, 3>(d, a).lazyProduct(m.middleRows<3>(a)) +
                         phi.block<1, 3>(d, v).lazyProduct(m.middleRows<3>(v)) +
                         phi.block<1, 3>(d, g).lazyProduct(m.middleRows<3>(g)) +
                         phi.block<1, 3>(d, b).lazyProduct(m.middleRows<3>(b)) + phi(d, n) * m.row(n) +
                         phi.block<1, 2>(d, l).lazyProduct(m.middleRows<2>(l)) + phi.block<1, 3>(d, k).lazyProduct(m.middleRows<3>(k)) +
                         phi.block<1, 2>(d, q).lazyProduct(m.middleRows<2>(q));
  StateMatrix out = pm;
  out.middleCols<3>(a).noalias() = pm.middleCols<3>(a).lazyProduct(phi.block<3, 3>(a, a).transpose()) +
                                   pm.middleCols<3>(g).lazyProduct(phi.block<3, 3>(a, g).transpose()) +
                                   pm.middleCols<3>(k).lazyProduct(phi.block<3, 3>(a, k).transpose()) +
                                   pm.middleCols<2>(q).lazyProduct(phi.block<3, 2>(a, q).transpose());
  out.middleCols<3>(v).noalias() = pm.middleCols<3>(a).lazyProduct(phi.block<3, 3>(v, a).transpose()) +
                                   pm.middleCols<3>(v).lazyProduct(phi.block<3, 3>(v, v).transpose()) +
                                   pm.middleCols<3>(g).lazyProduct(phi.block<3, 3>(v, g).transpose()) +
                                   pm.middleCols<3>(b).lazyProduct(phi.block<3, 3>(v, b).transpose()) +
                                   pm.col(n).lazyProduct(phi.block<3, 1>(v, n).transpose()) +
                                   pm.middleCols<2>(l).lazyProduct(phi.block<3, 2>(v, l).transpose()) +
                                   pm.middleCols<3>(k).lazyProduct(phi.block<3, 3>(v, k).transpose()) +
                                   pm.middleCols<2>(q).lazyProduct(phi.block<3, 2>(v, q).transpose());
  out.middleCols<3>(p).noalias() += pm.middleCols<3>(a).lazyProduct(phi.block<3, 3>(p, a).transpose()) +
                                    pm.middleCols<3>(v).lazyProduct(phi.block<3, 3>(p, v).transpose()) +
                                    pm.middleCols<3>(b).lazyProduct(phi.block<3, 3>(p, b).transpose()) +
                                    pm.col(n).lazyProduct(phi.block<3, 1>(p, n).transpose()) +
                                    pm.middleCols<2>(l).lazyProduct(phi.block<3, 2>(p, l).transpose());
  out.col(d).noalias() += pm.middleCols<3>(a).lazyProduct(phi.block<1, 3>(d, a).transpose()) +
                          pm.middleCols<3>(v).lazyProduct(phi.block<1, 3>(d, v).transpose()) +
                          pm.middleCols<3>(g).lazyProduct(phi.block<1, 3>(d, g).transpose()) +
                          pm.middleCols<3>(b).lazyProduct(phi.block<1, 3>(d, b).transpose()) + phi(d, n) * pm.col(n) +
                          pm.middleCols<2>(l).lazyProduct(phi.block<1, 2>(d, l).transpose()) + pm.middleCols<3>(k).lazyProduct(phi.block<1, 3>(d, k).transpose()) +
                          pm.middleCols<2>(q).lazyProduct(phi.block<1, 2>(d, q).transpose());
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

namespace {

// The states whose rows of phi are not the identity's: attitude, velocity, position, distance.
constexpr int kMoved = 10;
constexpr std::array<int, kMoved> kMovedStates = {0, 1, 2, 3, 4, 5, 6, 7, 8, kDistance};

}  // namespace

// predicted_covariance() in place. phi's other rows are the identity's, so phi m phi' keeps m
// between the other states, has (phi m)'s moved rows between them and the rest, and needs the full
// sandwich only between the moved states (10 x 10 of 25 x 25). Those rows of phi are sparse, and
// their zeros change with the motion (the lever arm's columns while the tool does not turn), so the
// products run over the entries that are not zero, each a whole column of m at once (m is
// symmetric: (phi m)' = m phi'). P comes out exactly symmetric, as symmetrize() left it.
void ErrorStateFilter::predict(const StateMatrix& phi, double dt, const ProcessNoise& noise) {
  const StateVector half_q = 0.5 * white_noise(dt, noise);
  p_.diagonal() += half_q;  // m = P + Q/2
  Eigen::Matrix<double, kMoved, kStates> rows;  // phi's moved rows
  for (int i = 0; i < kMoved; ++i) rows.row(i) = phi.row(kMovedStates[i]);
  // Each moved row's non-zero columns, listed without a branch: the pattern is the same from one
  // epoch to the next, but a branch per entry in the products would be mispredicted often.
  std::array<std::array<int, kStates>, kMoved> columns;
  std::array<int, kMoved> n_columns{};
  for (int i = 0; i < kMoved; ++i) {
    for (int k = 0; k < kStates; ++k) {
      columns[i][n_columns[i]] = k;
      n_columns[i] += rows(i, k) != 0.0 ? 1 : 0;
    }
  }
  // Each column of a product summed in a local (registers, not memory), its terms in increasing k.
  Eigen::Matrix<double, kStates, kMoved> m_phi;  // m phi[moved]'
  for (int i = 0; i < kMoved; ++i) {
    StateVector sum = StateVector::Zero();
    for (int c = 0; c < n_columns[i]; ++c) sum.noalias() += rows(i, columns[i][c]) * p_.col(columns[i][c]);
    m_phi.col(i) = sum;
  }
  const Eigen::Matrix<double, kMoved, kStates> phi_m = m_phi.transpose();
  Eigen::Matrix<double, kMoved, kMoved> moved;  // phi m phi'
  for (int j = 0; j < kMoved; ++j) {
    Eigen::Matrix<double, kMoved, 1> sum = Eigen::Matrix<double, kMoved, 1>::Zero();
    for (int c = 0; c < n_columns[j]; ++c) sum.noalias() += rows(j, columns[j][c]) * phi_m.col(columns[j][c]);
    moved.col(j) = sum;
  }
  for (int i = 0; i < kMoved; ++i) p_.col(kMovedStates[i]) = m_phi.col(i);
  for (int i = 0; i < kMoved; ++i) {
    for (int j = 0; j < kMoved; ++j) p_(kMovedStates[j], kMovedStates[i]) = 0.5 * (moved(i, j) + moved(j, i));
  }
  for (int i = 0; i < kMoved; ++i) p_.row(kMovedStates[i]) = p_.col(kMovedStates[i]).transpose();
  p_.diagonal() += half_q;
}

void add_noise(StateMatrix& p, const UnseenMotionNoise& extra) {
  p.block<3, 3>(kVel, kVel) += extra.velocity;
  p.block<3, 3>(kAtt, kAtt) += extra.attitude;
  static_assert(kVel == kAtt + 3, "the turn's u spans the attitude and the velocity");
  if (!extra.turn.isZero(0.0)) p.block<6, 6>(kAtt, kAtt) += extra.turn * extra.turn.transpose();
  if (extra.displacement.isZero(0.0)) return;
  const Eigen::Matrix4d add = extra.displacement * extra.displacement.transpose();
  p.block<3, 3>(kPos, kPos) += add.topLeftCorner<3, 3>();
  p.block<3, 1>(kPos, kDistance) += add.block<3, 1>(0, 3);
  p.block<1, 3>(kDistance, kPos) += add.block<1, 3>(3, 0);
  p(kDistance, kDistance) += add(3, 3);
}

void feed_back(const StateVector& dx, NavState& state, Eigen::Vector3d& gyro_bias, Eigen::Vector3d& accel_bias,
               Eigen::Vector2d* lever, Eigen::Vector3d* gyro_spin, double* mag_axial, Eigen::Vector2d* gyro_g) {
  // C(true) = (I + [phi x])^-1 C(est) = exp(-[phi x]) C(est): a rotation on the navigation side.
  state.q = (quaternion_from_rotation_vector(-dx.segment<3>(kAtt)) * state.q).normalized();
  state.v -= dx.segment<3>(kVel);
  state.p -= dx.segment<3>(kPos);
  gyro_bias -= dx.segment<3>(kGyroBias);
  accel_bias -= dx.segment<3>(kAccelBias);
  state.s -= dx[kDistance];
  if (lever != nullptr) *lever -= dx.segment<2>(kLever);
  if (gyro_spin != nullptr) *gyro_spin -= dx.segment<3>(kGyroSpin);
  if (mag_axial != nullptr) *mag_axial -= dx[kMagAxial];
  if (gyro_g != nullptr) *gyro_g -= dx.segment<2>(kGyroG);
}

template <int M>
int ErrorStateFilter::touched_states(const Eigen::Matrix<double, M, kStates>& h, std::array<int, kStates>& touched) {
  int n = 0;
  for (int j = 0; j < kStates; ++j)
    if (!h.col(j).isZero(0.0)) touched[n++] = j;
  return n;
}

template <int M>
Eigen::Matrix<double, kStates, M> ErrorStateFilter::p_ht(const Eigen::Matrix<double, M, kStates>& h) const {
  std::array<int, kStates> touched{};
  const int n_touched = touched_states(h, touched);
  Eigen::Matrix<double, kStates, M> pht = Eigen::Matrix<double, kStates, M>::Zero();
  for (int t = 0; t < n_touched; ++t) pht.noalias() += p_.col(touched[t]) * h.col(touched[t]).transpose();
  return pht;
}

template <int M>
StateVector ErrorStateFilter::update(const Eigen::Matrix<double, M, 1>& r, const Eigen::Matrix<double, M, kStates>& h,
                                   const Eigen::Matrix<double, M, M>& noise, double* nis) {
  return update(r, h, noise, p_ht(h), nis);
}
template <int M>
StateVector ErrorStateFilter::update(const Eigen::Matrix<double, M, 1>& r, const Eigen::Matrix<double, M, kStates>& h,
                                   const Eigen::Matrix<double, M, M>& noise,
                                   const Eigen::Matrix<double, kStates, M>& pht, double* nis) {
  // H P H' over H's non-zero columns only, as P H'.
  std::array<int, kStates> touched{};
  const int n_touched = touched_states(h, touched);
  Eigen::Matrix<double, M, M> s = noise;
  for (int t = 0; t < n_touched; ++t) s.noalias() += h.col(touched[t]) * pht.row(touched[t]);
  // M <= 3: the closed-form inverse of a small symmetric positive definite matrix.
  const Eigen::Matrix<double, M, M> s_inv = s.inverse();
  Eigen::Matrix<double, kStates, M> k = pht.lazyProduct(s_inv);
  if (considered_ >= 0) k.row(considered_).setZero();
  if (nis != nullptr) *nis = r.dot(s_inv * r);
  // Joseph form (I-KH) P (I-KH)' + K R K', multiplied out: P - K(HP) - (K(HP))' + K S K' (the
  // same matrix for any gain K), at 25 x 25 x M products instead of 25 x 25 x 25 ones. With
  // W = K S / 2 - P H' the change is K W' + W K': symmetric, so one triangle is computed and
  // mirrored (P stays exactly symmetric).
  const Eigen::Matrix<double, kStates, M> w = 0.5 * k.lazyProduct(s) - pht;
  for (int j = 0; j < kStates; ++j) {
    for (int i = 0; i <= j; ++i) {
      double d = 0;
      for (int m = 0; m < M; ++m) d += k(i, m) * w(j, m) + w(i, m) * k(j, m);
      p_(i, j) += d;
      p_(j, i) = p_(i, j);
    }
  }
  return k * r;
}

// The measurement sizes the navigator uses (error_state_filter.hpp).
#define PLUMB_ERROR_STATE_FILTER_UPDATES(M)                                                                   \
  template Eigen::Matrix<double, kStates, M> ErrorStateFilter::p_ht<M>(const Eigen::Matrix<double, M, kStates>&) \
      const;                                                                                                  \
  template StateVector ErrorStateFilter::update<M>(const Eigen::Matrix<double, M, 1>&,                        \
                                                   const Eigen::Matrix<double, M, kStates>&,                  \
                                                   const Eigen::Matrix<double, M, M>&, double*);              \
  template StateVector ErrorStateFilter::update<M>(                                                           \
      const Eigen::Matrix<double, M, 1>&, const Eigen::Matrix<double, M, kStates>&,                           \
      const Eigen::Matrix<double, M, M>&, const Eigen::Matrix<double, kStates, M>&, double*);
PLUMB_ERROR_STATE_FILTER_UPDATES(1)
PLUMB_ERROR_STATE_FILTER_UPDATES(2)
PLUMB_ERROR_STATE_FILTER_UPDATES(3)
#undef PLUMB_ERROR_STATE_FILTER_UPDATES

}  // namespace plumb::strapdown
