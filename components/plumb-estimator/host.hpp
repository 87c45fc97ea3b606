// The estimator host loop, separate from main() so that it reads as one piece.
#pragma once

#include <string>
#include <vector>

#include "plumb/components/cli.hpp"
#include "plumb/transport/topic_names.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::estimator_component {

struct HostOptions {
  components::TransportOptions transport;
  std::vector<std::string> plugins;
  std::string name;  // what `plumb component` and `plumb param` call this host; "" -> the computer's host name
  std::string input_topic = transport::topic_names::kSensorCalibrated;
  double window_s = 10;
  std::vector<std::string> params;
  std::string tool_id;
  bool reliable = false;
  double idle_flush_s = 2;
  int max_estimates = 0;
  double timeout_s = 0;
  double linger_s = 1;  // after --count is reached, so reliable readers get the last estimates
  bool quiet = false;
  bool compare_truth = false;  // print each estimate's error against the simulator's truth
  std::string truth_topic = transport::topic_names::kSimTruth;
  // Where the host keeps the last sequence number it took of each tool, for its next instance
  // (resume_record.hpp); "" is default_state_dir(). no_state: keep nothing, count nothing.
  std::string state_dir;
  bool no_state = false;
};

int run_host(const HostOptions& options);

}  // namespace plumb::estimator_component
