// `plumb launch FILE.yaml`: start a set of plumb programs on this computer (launch_file.hpp).
#pragma once

#include <CLI/CLI.hpp>

namespace plumb::cli {

void add_launch_command(CLI::App& app);

}  // namespace plumb::cli
