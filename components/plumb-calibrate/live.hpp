// plumb-calibrate --live: guides the operator through the positions over DDS.
#pragma once

#include "options.hpp"

namespace plumb::calibrate_component {

int run_live(const Options& o);

}  // namespace plumb::calibrate_component
