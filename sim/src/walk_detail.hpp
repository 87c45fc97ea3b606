// Internals of the walk simulator shared between its source files (private to sim/src): the swing
// profiles and the scenario checks.
#pragma once

#include "plumb/sim/walk.hpp"

namespace plumb::sim::detail {

// A profile of the swing time tau in [0, 1] with its first two derivatives in tau.
struct SwingProfile {
  double value = 0, rate = 0, rate_dot = 0;
};

// 0 -> 1 with zero first, second and third derivatives at both ends (septic smoothstep).
SwingProfile swing_step(double tau);
// 0 -> 1 -> 0, peak 1 at tau = 1/2, zero first three derivatives at both ends.
SwingProfile swing_bump(double tau);
// Positive lobe then negative lobe, peaks +-1 at tau = 1/3 and 2/3, zero first three derivatives at
// both ends.
SwingProfile swing_wave(double tau);

// Throw std::invalid_argument naming the bad parameter: the loop and its timing (by WalkPath), the
// sensors and the environment (by WalkSimulator).
void validate_walk_path(const WalkScenario& scenario);
void validate_walk_sensors(const WalkScenario& scenario);

}  // namespace plumb::sim::detail
