#include "plumb/estimator/loader.hpp"

#include <set>

namespace plumb::estimator {
namespace {

const plumb_estimator_plugin* open_estimator(const plugin::Found& found) {
  const auto* entry = plugin::open<plumb_estimator_plugin>(kEstimatorPlugins, found);
  if (entry->create == nullptr || entry->destroy == nullptr) throw plugin::Error(found.path, "plugin has no create/destroy");
  return entry;
}

}  // namespace

// libplumb_estimator_api.so shares the prefix and is not a plugin.
const plugin::Kind kEstimatorPlugins{"estimator", "libplumb_estimator_", "PLUMB_ESTIMATOR_PATH",
                                     "plumb_estimator_plugin", PLUMB_ESTIMATOR_ABI, "api"};

std::vector<plugin::Found> list_plugins() { return plugin::find(kEstimatorPlugins); }

std::vector<FoundPlugin> find_plugins() {
  std::vector<FoundPlugin> out;
  for (const auto& f : list_plugins()) {
    FoundPlugin p{f.name, f.path, {}, {}};
    try {
      const auto* entry = open_estimator(f);
      p.description = entry->description != nullptr ? entry->description : "";
    } catch (const plugin::Error& e) {
      p.error = e.reason;
    }
    out.push_back(std::move(p));
  }
  return out;
}

EstimatorPtr load_estimator(const std::string& name) {
  const plugin::Found found = plugin::locate(kEstimatorPlugins, name);
  const auto* entry = open_estimator(found);
  Estimator* raw = entry->create();
  if (raw == nullptr) throw plugin::Error(found.path, "failed to create an estimator");
  EstimatorPtr estimator(raw, entry->destroy);
  if (const std::string own = estimator->info().name; own != name)
    throw plugin::Error(found.path, "calls itself '" + own + "': a plugin's name is its file's (libplumb_estimator_" + name + ".so)");
  return estimator;
}

Runner load_runner(const std::vector<std::string>& names) {
  Runner runner;
  std::set<std::string> seen;
  for (const auto& name : names) {
    if (!seen.insert(name).second) throw ParameterError("estimator '" + name + "' is named twice");
    runner.add(name, load_estimator(name));
  }
  return runner;
}

}  // namespace plumb::estimator
