// `plumb transports` and `plumb plugins`: which plugins are installed, and whether they load.
#pragma once

#include "verbs.hpp"

namespace plumb::cli {

void add_transports_verb(CLI::App& app, Verbs& verbs);
void add_plugins_verb(CLI::App& app, Verbs& verbs);

}  // namespace plumb::cli
