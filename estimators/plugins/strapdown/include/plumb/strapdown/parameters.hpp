// The strapdown plugin's named parameters and their mapping onto
// NavigatorConfig. Unknown names and bad values throw estimator::ParameterError.
#pragma once

#include <vector>

#include "plumb/estimator/estimator.hpp"
#include "plumb/strapdown/navigator.hpp"

namespace plumb::strapdown {

std::vector<estimator::ParameterSpec> parameter_specs();
NavigatorConfig parse_parameters(const estimator::Parameters& params);

}  // namespace plumb::strapdown
