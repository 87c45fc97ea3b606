// The line plumb-estimator prints per estimate, for a person watching: angles in [0, 360) as
// rounded, an invalid estimate shown by its reason rather than by numbers nobody should use, and,
// when the truth is known (a simulation), the error against it.
#pragma once

#include <optional>
#include <string>

#include "plumb/core/estimate.hpp"
#include "plumb/topics/all.hpp"

namespace plumb::estimator_component {

// `degrees` wrapped into [0, 360) after rounding to `decimals`, so that 359.9996 prints 0.000, not 360.000.
std::string format_angle(double degrees, int decimals);

// One line, no newline. `truth`: the simulator's truth at the window's end, if known.
std::string estimate_line(const Estimate& e, const std::optional<topics::Truth>& truth);

}  // namespace plumb::estimator_component
