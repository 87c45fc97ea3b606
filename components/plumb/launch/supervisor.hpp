// plumb launch's loop: starts every program of a launch file, prefixes each line of their output
// with their name, restarts them per their policy (never a usage error, exit status 2), and stops
// them all on SIGINT or SIGTERM, when a required one fails for good, or when one marked on_exit:
// shutdown ends. Any other program that fails for good fails alone.
#pragma once

#include <ostream>
#include <vector>

#include "launch_file.hpp"

namespace plumb::launch {

struct SupervisorOptions {
  double stop_timeout_s = 10;  // after SIGINT, this long before SIGKILL
};

// Returns the exit status: 0 when every program ended well or was stopped on request, 1 when one
// failed for good (alone or not). Throws std::invalid_argument (FILE:LINE) for a program that cannot be found,
// before anything is started.
int supervise(const std::vector<ProgramSpec>& programs, const SupervisorOptions& options, std::ostream& out,
              std::ostream& err);

}  // namespace plumb::launch
