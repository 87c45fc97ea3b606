// Plugin parameters kept in a YAML file (`--params-file FILE.yaml`), the way a ROS 2 user keeps
// a node's parameters. One layout:
//
//   strapdown:              # a plugin's name
//     latitude_deg: 35      # then its parameters, KEY: VALUE, one per line
//     gravity: 9.80665
//
// Each entry becomes the assignment PLUGIN.KEY=VALUE tagged with its file and line
// (estimator::with_origin), so that a key the plugin does not declare, or a plugin that is not
// selected, is refused naming the file and the line.
#pragma once

#include <string>
#include <vector>

namespace plumb::components {

// The file's entries in file order. Throws estimator::ParameterError ("FILE:LINE: what") for a
// file that cannot be read, is not YAML, or is not in the layout above (a plugin without a map of
// parameters, a value that is a list or a map or empty, a key given twice).
std::vector<std::string> read_params_file(const std::string& path);

}  // namespace plumb::components
