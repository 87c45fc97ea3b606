// The host's output: one attitude topic per plugin (plumb/attitude/<plugin>), and for navigators
// (plugins that use gyros) their position and velocity on plumb/navigation/<plugin>.
#pragma once

#include <map>
#include <string>

#include "plumb/core/estimate.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::estimator_component {

class EstimatePublication {
 public:
  explicit EstimatePublication(transport::Participant& participant) : participant_(participant) {}
  // Creates the plugin's writers now, so readers can match before the first estimate.
  void add(const std::string& plugin, bool navigator);
  void publish(const Estimate& e, const std::string& tool_id);

 private:
  transport::Participant& participant_;
  std::map<std::string, transport::Writer<topics::Attitude>> attitude_;
  std::map<std::string, transport::Writer<topics::Navigation>> navigation_;
};

}  // namespace plumb::estimator_component
