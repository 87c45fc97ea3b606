// Finds and loads estimator plugins (libplumb_estimator_<name>.so) by name, through the plugin
// facility (plumb/plugin/library.hpp: search path $PLUMB_ESTIMATOR_PATH then the installed
// libraries' folder, identity by file name, ABI check, libraries never unloaded).
#pragma once

#include <string>
#include <vector>

#include "plumb/estimator/estimator.hpp"
#include "plumb/estimator/runner.hpp"
#include "plumb/plugin/library.hpp"

namespace plumb::estimator {

extern const plugin::Kind kEstimatorPlugins;

struct FoundPlugin {
  std::string name;
  std::string path;
  std::string description;  // empty when not described or not loadable
  std::string error;        // why it could not be loaded
};

// Every plugin on the search path by file name; nothing is loaded.
std::vector<plugin::Found> list_plugins();
// The same, each opened to read its description (runs the plugins' entry points).
std::vector<FoundPlugin> find_plugins();

// Throws plugin::Error naming the file and the reason, or the plugins found when `name` is
// unknown. The estimator's info().name must be the file's plugin name.
EstimatorPtr load_estimator(const std::string& name);

// A runner with each named plugin loaded (not yet configured). A name given twice is refused:
// the two would publish on one topic.
Runner load_runner(const std::vector<std::string>& names);

}  // namespace plumb::estimator
