// The plugins an estimator host runs and the parameters each one has now: what a tool that appears
// later starts with, and the checks a change asked for at run time (plumb component load, plumb
// param set) passes before any runner is touched. No DDS: the host applies what this accepts.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "plumb/estimator/runner.hpp"

namespace plumb::estimator_component {

// A load request's assignments as they travel (ComponentRequest.value: "KEY=VALUE;PLUGIN.KEY=VALUE"),
// back to the --param list; empty pieces are skipped.
std::vector<std::string> split_assignments(const std::string& text);

class Lineup {
 public:
  struct Entry {
    std::string name;
    estimator::Info info;
    estimator::Parameters parameters;  // as given (--param, --window, param set); defaults not filled in
  };
  // A parameter's value in use: the one given, else the plugin's default.
  struct Value {
    std::string plugin, name, value, default_value;
  };

  // The command line's plugins, --param assignments and --window: refused exactly as at start
  // (estimator::ParameterError, plugin::Error), since the first runner is made here.
  Lineup(const std::vector<std::string>& plugins, const std::vector<std::string>& assignments, double window_s);

  // A runner with every plugin loaded and configured as now (the first tool's, or a new tool's).
  estimator::Runner make_runner() const;
  const std::vector<Entry>& entries() const { return entries_; }
  const Entry* find(const std::string& plugin) const;

  // The checks of each change; each throws the message the command line gives for the same mistake
  // and changes nothing. On success the lineup has the change and returns the plugin's parameters.
  //   load: `assignments` as --param (KEY=VALUE or PLUGIN.KEY=VALUE), the host's --window as at start.
  estimator::Parameters load(const std::string& plugin, const std::vector<std::string>& assignments);
  //   unload: a plugin that is loaded, and not the last one (a host estimates something).
  void unload(const std::string& plugin);
  //   set: as --param PLUGIN.NAME=VALUE would be refused, then the value as the plugin checks it.
  estimator::Parameters set(const std::string& plugin, const std::string& name, const std::string& value);

  // param get (one name) and dump (every parameter the plugin declares).
  Value get(const std::string& plugin, const std::string& name) const;
  std::vector<Value> dump(const std::string& plugin) const;

 private:
  std::vector<estimator::Info> infos() const;
  const Entry& loaded(const std::string& plugin) const;  // throws "estimator 'X' is not loaded ..."
  std::vector<Entry> entries_;
  double window_s_;
};

}  // namespace plumb::estimator_component
