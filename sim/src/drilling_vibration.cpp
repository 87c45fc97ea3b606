// Lateral vibration and shocks of a drilling tool: zero-mean accelerations on x and y added to the
// specific force only while drilling, scaled by the drive factor so they fade in and out with the
// speed ramps and vanish while the tool stands (the stillness a navigator relies on stays exact).
#include <algorithm>
#include <cmath>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/drilling.hpp"

namespace plumb::sim {

Eigen::Vector3d DrillingSimulator::vibration_at(double t, double drive) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  const auto& v = scenario_.vibration;
  if (tones_.active() && drive > 0) out.head<2>() = drive * tones_.at(t);
  // Poisson arrivals (as on the platform); a shock keeps the drive of its start, and one arriving
  // while the tool stands is lost.
  const double duration = std::max(v.shock_duration_s, (v.shock_rebounds ? 4.0 : 2.0) / scenario_.sample_rate_hz);
  while (t >= next_shock_) {
    // A rebound is never cut short (its velocity and displacement come back only whole): one that
    // arrives during it starts when it ends.
    if (v.shock_rebounds && next_shock_ < shock_until_) next_shock_ = shock_until_;
    if (t < next_shock_) break;
    shock_start_ = next_shock_;
    shock_until_ = shock_start_ + duration;
    shock_dir_ = 2.0 * kPi * std::uniform_real_distribution<double>(0.0, 1.0)(vib_rng_);
    shock_drive_ = trajectory_.at(shock_start_).drive;
    next_shock_ += std::exponential_distribution<double>(v.shock_rate_hz)(vib_rng_);
  }
  if (t >= shock_start_ && t < shock_until_ && drive > 0) {
    const double u = (t - shock_start_) / duration;
    // A rebound: out to the wall and back, a displacement that ends where it began, so the velocity
    // and the position both come back (cos 2 pi u - cos 4 pi u has a zero first and second
    // integral over the shock, and is zero at its ends; its peak, at mid-shock, is 2). One full sine
    // cycle instead comes back in velocity only, and leaves the tool peak T^2 / (2 pi) away from the
    // truth: 7.5 cm for 30 g over 40 ms, every shock.
    const double shape = v.shock_rebounds ? 0.5 * (std::cos(2.0 * kPi * u) - std::cos(4.0 * kPi * u)) : std::sin(kPi * u);
    const double a = shock_drive_ * v.shock_peak * shape;
    out.x() += a * std::cos(shock_dir_);
    out.y() += a * std::sin(shock_dir_);
  }
  return out;
}

}  // namespace plumb::sim
