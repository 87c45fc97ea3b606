// The host's output: one attitude topic per plugin (plumb/attitude/<plugin>), and for navigators
// (plugins that use gyros) their position and velocity on plumb/navigation/<plugin>.
#pragma once

#include <chrono>
#include <map>
#include <optional>
#include <utility>
#include <string>

#include "plumb/core/estimate.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::estimator_component {

class EstimatePublication {
 public:
  explicit EstimatePublication(transport::Participant& participant) : participant_(participant) {}
  // Creates the plugin's writers now, so readers can match before the first estimate; a plugin
  // retired a moment ago gets its writers back.
  void add(const std::string& plugin, bool navigator);
  void publish(const Estimate& e, const std::string& tool_id);
  // An unloaded plugin's writers: kept a few seconds, so that reliable readers get its last
  // estimate (a writer deleted at once may take unacknowledged samples with it), then deleted by sweep.
  void retire(const std::string& plugin);
  void sweep();

 private:
  struct Writers {
    std::optional<transport::Writer<topics::Attitude>> attitude;
    std::optional<transport::Writer<topics::Navigation>> navigation;
  };
  transport::Participant& participant_;
  std::map<std::string, Writers> writers_;
  std::map<std::string, std::pair<std::chrono::steady_clock::time_point, Writers>> retired_;  // plugin -> (until, writers)
};

}  // namespace plumb::estimator_component
