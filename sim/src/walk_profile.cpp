// The swing profiles of the walk, polynomials in q = tau (1 - tau): every one has a factor of at
// least q^3 in its first derivative, so the foot lands and lifts off with zero velocity,
// acceleration and jerk, and zero angular rate and angular acceleration.
#include "walk_detail.hpp"

namespace plumb::sim::detail {
namespace {

// w peaks where d/dtau [q^4 (1 - 2 tau)] = 0, at tau = 1/2 -+ 1/6, with |q^4 (1 - 2 tau)| = 16/19683.
constexpr double kWaveScale = 19683.0 / 16.0;

}  // namespace

SwingProfile swing_step(double tau) {
  const double q = tau * (1.0 - tau), dq = 1.0 - 2.0 * tau;
  const double t4 = tau * tau * tau * tau;
  return {t4 * (35.0 - 84.0 * tau + 70.0 * tau * tau - 20.0 * tau * tau * tau),  // 140 q^3 integrated
          140.0 * q * q * q, 420.0 * q * q * dq};
}

SwingProfile swing_bump(double tau) {
  // 256 q^4: (q')' = -2.
  const double q = tau * (1.0 - tau), dq = 1.0 - 2.0 * tau;
  return {256.0 * q * q * q * q, 1024.0 * q * q * q * dq, 1024.0 * q * q * (3.0 * dq * dq - 2.0 * q)};
}

SwingProfile swing_wave(double tau) {
  // K q^4 q': derivative K q^3 (4 q'^2 + q q'') = K q^3 (4 q'^2 - 2 q), and again
  // K (3 q^2 q' (4 q'^2 - 2 q) + q^3 (-16 q' - 2 q')) = K q^2 q' (12 q'^2 - 24 q).
  const double q = tau * (1.0 - tau), dq = 1.0 - 2.0 * tau;
  return {kWaveScale * q * q * q * q * dq, kWaveScale * q * q * q * (4.0 * dq * dq - 2.0 * q),
          kWaveScale * q * q * dq * (12.0 * dq * dq - 24.0 * q)};
}

}  // namespace plumb::sim::detail
