// Rauch-Tung-Striebel smoother over the closed-loop error-state filter's epochs (offline).
//
// Per filter epoch k it keeps: the whole-value state after that epoch's feedback, P(k|k), the
// transition from epoch k-1 with its dt and the process noise the filter used (the figures as the
// lateral velocity's measured excess raised them, and the unresolved vibration's velocity
// covariance: Q is recomputed from them), and the correction fed back at k. The backward pass:
//   P(k+1|k) = Phi P(k|k) Phi' + Q,   G = P(k|k) Phi' P(k+1|k)^-1,
//   dx(k|N) = G (dx(k+1|N) + c(k+1)),  P(k|N) = P(k|k) + G (P(k|N+1) - P(k+1|k)) G',
// where dx(k|N) is the smoothed error of the stored (post-feedback) state and c(k+1) the
// correction applied at k+1 (the stored state at k+1 is the prediction minus c(k+1)).
// Memory: about 8 kB per epoch (P upper triangle 325, Phi 625, state 19, correction 25, noise 15
// doubles), independent of the sample rate: a 1-hour run at the default 20 Hz filter rate keeps
// 72,000 epochs, 580 MB; at 5 Hz, 145 MB (parameter kf_rate_hz).
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/mechanization.hpp"

namespace plumb::strapdown {

struct SmoothedEpoch {
  NavState state;
  Eigen::Vector3d gyro_bias = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias = Eigen::Vector3d::Zero();
  StateMatrix p = StateMatrix::Zero();
};

class RtsSmoother {
 public:
  void clear() { epochs_.clear(); }
  // A state the filter kept out of its updates (ErrorStateFilter::consider; -1: none): kept out of
  // the backward pass too, its smoothed error zero at every epoch.
  void consider(int state) { considered_ = state; }
  std::size_t size() const { return epochs_.size(); }
  // Epoch k: phi, dt and process noise of the prediction from epoch k-1 (ignored for the first),
  // the correction applied at k, the state and covariance after it.
  void store(const StateMatrix& phi, double dt, const ProcessNoise& noise, const UnseenMotionNoise& extra,
             const StateVector& correction, const NavState& state, const Eigen::Vector3d& gyro_bias,
             const Eigen::Vector3d& accel_bias, const StateMatrix& p);
  // Runs the backward pass; calls visit(k, smoothed) from the last epoch to the first.
  template <class Visit>
  void smooth(Visit&& visit) const;
  std::size_t bytes_per_epoch() const { return sizeof(Epoch); }

 private:
  struct Epoch {
    double dt = 0;
    ProcessNoise noise;
    double velocity_noise[6];  // upper triangle
    double displacement_noise[4];
    double turn_noise[6];
    double attitude_noise[6];  // upper triangle
    double p_upper[kStates * (kStates + 1) / 2];
    double phi[kStates * kStates];
    double correction[kStates];
    double q[4], v[3], p[3], s = 0, bg[3], ba[3];
  };
  StateMatrix covariance(const Epoch& e) const;
  // P(k+1|k) as the filter had it.
  static StateMatrix predicted(const Epoch& next, const StateMatrix& phi, const StateMatrix& pk);
  SmoothedEpoch whole(const Epoch& e) const;
  std::vector<Epoch> epochs_;
  int considered_ = -1;
};

template <class Visit>
void RtsSmoother::smooth(Visit&& visit) const {
  if (epochs_.empty()) return;
  const std::size_t n = epochs_.size();
  StateVector dx = StateVector::Zero();  // smoothed error of epoch k+1's stored state
  StateMatrix ps = covariance(epochs_[n - 1]);
  {
    SmoothedEpoch last = whole(epochs_[n - 1]);
    last.p = ps;
    visit(n - 1, last);
  }
  for (std::size_t k = n - 1; k-- > 0;) {
    const Epoch& next = epochs_[k + 1];
    const StateMatrix pk = covariance(epochs_[k]);
    const StateMatrix phi = Eigen::Map<const StateMatrix>(next.phi);
    const StateMatrix pred = predicted(next, phi, pk);
    // G = P Phi' pred^-1, i.e. G' = pred^-1 Phi P (pred is symmetric positive definite).
    StateMatrix g = pred.ldlt().solve(phi * pk).transpose();
    if (considered_ >= 0) g.row(considered_).setZero();
    const StateVector c = Eigen::Map<const StateVector>(next.correction);
    dx = g * (dx + c);
    ps = pk + g * (ps - pred) * g.transpose();
    ps = 0.5 * (ps + ps.transpose()).eval();
    SmoothedEpoch out = whole(epochs_[k]);
    StateVector d = dx;
    feed_back(d, out.state, out.gyro_bias, out.accel_bias);
    out.p = ps;
    visit(k, out);
  }
}

}  // namespace plumb::strapdown
