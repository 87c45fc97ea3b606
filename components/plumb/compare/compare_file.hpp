// plumb compare --input: estimator plugins side by side on a recorded run (sensor CSV or MCAP
// recording), where there is no truth: each plugin's spread and sigma, and its agreement with the
// first plugin against their combined sigma (components/compare agreement.hpp).
#pragma once

#include <string>
#include <vector>

#include "plumb/components/import_options.hpp"

namespace plumb::cli {

struct CompareFileOptions {
  std::vector<std::string> estimators;
  std::string input;
  std::string topic;
  double window_s = 1;
  double match_s = 0.5;
  std::vector<std::string> params;
  std::string csv_path;
  bool skip_bad_rows = false;
  components::ImportOptions import;
};

int compare_file(const CompareFileOptions& options);

}  // namespace plumb::cli
