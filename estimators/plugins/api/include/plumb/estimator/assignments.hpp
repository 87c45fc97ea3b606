// Command-line parameters for several estimators at once, one grammar for every tool: KEY=VALUE
// goes to every selected estimator that declares KEY, PLUGIN.KEY=VALUE to that plugin only, and
// `window` (when given) to every one that has a window.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "plumb/estimator/estimator.hpp"

namespace plumb::estimator {

bool declares_parameter(const Info& info, const std::string& name);

// One Parameters per estimator, in order. Throws ParameterError for an assignment that is not
// [PLUGIN.]KEY=VALUE or whose KEY no (such) estimator declares (a typo must not pass silently).
std::vector<Parameters> assign_parameters(const std::vector<Info>& estimators, const std::vector<std::string>& assignments,
                                          std::optional<double> window_s);

}  // namespace plumb::estimator
