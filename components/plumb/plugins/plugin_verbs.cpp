#include "plugins/plugin_verbs.hpp"

namespace plumb::cli {

void add_plugin_verbs(CLI::App& app, Verbs& verbs) {
  add_transports_verb(app, verbs);
  add_plugins_verb(app, verbs);
}

}  // namespace plumb::cli
