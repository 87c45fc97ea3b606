#include "plumb/components/params_file.hpp"

#include <fstream>
#include <set>

#include <yaml-cpp/yaml.h>

#include "plumb/estimator/assignments.hpp"
#include "plumb/estimator/estimator.hpp"

namespace plumb::components {
namespace {

using estimator::ParameterError;

// yaml-cpp counts lines from 0; editors and compilers from 1.
std::string at(const std::string& path, const YAML::Mark& mark) {
  return path + ":" + std::to_string(mark.line + 1);
}

const char* kLayout = "expected PLUGIN: then indented KEY: VALUE lines";

void read_plugin(const std::string& path, const std::string& plugin, const YAML::Node& entries,
                 std::vector<std::string>& out) {
  if (!entries.IsMap())
    throw ParameterError(at(path, entries.Mark()) + ": plugin '" + plugin + "' holds no KEY: VALUE lines (" + kLayout + ")");
  std::set<std::string> seen;
  for (const auto& entry : entries) {
    const YAML::Node& key = entry.first;
    const YAML::Node& value = entry.second;
    if (!key.IsScalar()) throw ParameterError(at(path, key.Mark()) + ": a parameter's name must be a plain word");
    const std::string name = key.Scalar();
    if (!seen.insert(name).second)
      throw ParameterError(at(path, key.Mark()) + ": '" + plugin + "." + name + "' is given twice");
    if (!value.IsScalar())
      throw ParameterError(at(path, key.Mark()) + ": '" + plugin + "." + name + "' needs one value (" +
                           (value.IsNull() ? "it is empty" : "a list or map is not a parameter value") + ")");
    out.push_back(estimator::with_origin(at(path, key.Mark()), plugin + "." + name + "=" + value.Scalar()));
  }
}

}  // namespace

std::vector<std::string> read_params_file(const std::string& path) {
  // yaml-cpp's LoadFile says only "bad file" for a missing file: say which and why.
  if (!std::ifstream(path)) throw ParameterError("cannot read parameters file '" + path + "'");
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ParameterError(at(path, e.mark) + ": not YAML: " + e.msg);
  }
  if (root.IsNull()) throw ParameterError(path + ": no parameters in the file (" + kLayout + ")");
  if (!root.IsMap()) throw ParameterError(at(path, root.Mark()) + ": " + kLayout);
  std::vector<std::string> out;
  std::set<std::string> plugins;
  for (const auto& section : root) {
    if (!section.first.IsScalar()) throw ParameterError(at(path, section.first.Mark()) + ": " + kLayout);
    const std::string plugin = section.first.Scalar();
    if (!plugins.insert(plugin).second)
      throw ParameterError(at(path, section.first.Mark()) + ": plugin '" + plugin + "' is given twice");
    read_plugin(path, plugin, section.second, out);
  }
  return out;
}

}  // namespace plumb::components
