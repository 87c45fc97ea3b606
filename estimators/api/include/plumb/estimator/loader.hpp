// Finds and loads estimator plugins by name at run time. Search order: $PLUMB_ESTIMATOR_PATH
// (':'-separated folders), then the folder of libplumb_estimator_api.so. Each instance keeps its
// plugin library loaded for as long as it lives, so instances may outlive the loader's callers.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "plumb/estimator/estimator.hpp"

namespace plumb::estimator {

struct FoundPlugin {
  std::string name;
  std::string path;
  std::string description;  // empty when the library could not be loaded
  std::string error;        // why it could not be loaded
};

std::vector<FoundPlugin> find_plugins();

using EstimatorPtr = std::unique_ptr<Estimator, std::function<void(Estimator*)>>;

// Throws std::runtime_error naming the plugins found when `name` is unknown or broken.
EstimatorPtr load_estimator(const std::string& name);

}  // namespace plumb::estimator
