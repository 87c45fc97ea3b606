// A walk compiled into footprints and timed swings: equal strides along each leg, a footprint at a
// corner pointing halfway through the turn, stance lengths drawn from the seed (on a stream of their
// own, so the path does not depend on the sample rate or the IMU grade).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "plumb/core/attitude.hpp"
#include "walk_detail.hpp"

namespace plumb::sim {
namespace {

constexpr std::uint64_t kStanceStream = 0x165667b19e3779f9ULL;
// The legs' own geometry must close the loop; what round-off leaves is then removed exactly.
constexpr double kClosureTolerance = 1e-6;  // m

}  // namespace

WalkPath::WalkPath(const WalkScenario& s) {
  detail::validate_walk_path(s);
  clearance_ = s.clearance_m;
  pitch_ = s.pitch_deg * kDeg;
  roll_ = s.roll_deg * kDeg;

  double heading = s.heading_deg * kDeg;
  footprints_.push_back({Eigen::Vector3d::Zero(), heading - 0.5 * s.legs.back().turn_deg * kDeg});
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (const WalkLeg& leg : s.legs) {
    const double stride = leg.stride_m > 0 ? leg.stride_m : s.stride_m;
    const long n = std::max(1L, std::lround(leg.length_m / stride));
    const double turn = leg.turn_deg * kDeg;
    // Up is -down: a climb lowers the down coordinate.
    const Eigen::Vector3d step(leg.length_m / n * std::cos(heading), leg.length_m / n * std::sin(heading),
                               -leg.climb_m / n);
    for (long i = 1; i <= n; ++i) {
      p += step;
      footprints_.push_back({p, i < n ? heading : heading + 0.5 * turn});
    }
    heading += turn;
  }
  if (footprints_.back().position.norm() > kClosureTolerance)
    throw std::invalid_argument("invalid walk scenario: the legs end " +
                                std::to_string(footprints_.back().position.norm()) +
                                " m from the start (a closed loop returns there)");
  footprints_.back().position.setZero();

  std::mt19937_64 rng(s.seed ^ kStanceStream);
  std::uniform_real_distribution<double> stance(s.stance_min_s, s.stance_max_s);
  const double swing = 1.0 / s.cadence_hz - 0.5 * (s.stance_min_s + s.stance_max_s);
  double t = s.initial_still_s;
  for (std::size_t k = 0; k + 1 < footprints_.size(); ++k) {
    if (k > 0) t += s.stance_min_s == s.stance_max_s ? s.stance_min_s : stance(rng);
    swings_.push_back({t, t + swing, k});
    t += swing;
  }
  duration_ = t + s.final_still_s;
}

double WalkPath::horizontal_length_m() const {
  double sum = 0;
  for (std::size_t k = 1; k < footprints_.size(); ++k)
    sum += (footprints_[k].position - footprints_[k - 1].position).head<2>().norm();
  return sum;
}

double WalkPath::length_m() const {
  double sum = 0;
  for (std::size_t k = 1; k < footprints_.size(); ++k)
    sum += (footprints_[k].position - footprints_[k - 1].position).norm();
  return sum;
}

}  // namespace plumb::sim
