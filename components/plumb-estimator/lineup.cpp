#include "lineup.hpp"

#include <algorithm>

#include "plumb/core/edit_distance.hpp"
#include "plumb/estimator/assignments.hpp"
#include "plumb/estimator/loader.hpp"

namespace plumb::estimator_component {

using estimator::ParameterError;
using estimator::Parameters;

std::vector<std::string> split_assignments(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto end = std::min(text.find(';', start), text.size());
    if (end > start) out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

Lineup::Lineup(const std::vector<std::string>& plugins, const std::vector<std::string>& assignments, double window_s)
    : window_s_(window_s) {
  estimator::Runner runner = estimator::load_runner(plugins);
  runner.configure(assignments, window_s);  // the start's refusals, word for word
  for (const auto& slot : runner.slots()) entries_.push_back({slot.name, slot.estimator->info(), slot.parameters});
}

estimator::Runner Lineup::make_runner() const {
  estimator::Runner runner;
  std::vector<Parameters> parameters;
  for (const auto& e : entries_) {
    runner.add(e.name, estimator::load_estimator(e.name));
    parameters.push_back(e.parameters);
  }
  runner.configure(parameters);
  return runner;
}

const Lineup::Entry* Lineup::find(const std::string& plugin) const {
  for (const auto& e : entries_)
    if (e.name == plugin) return &e;
  return nullptr;
}

std::vector<estimator::Info> Lineup::infos() const {
  std::vector<estimator::Info> out;
  for (const auto& e : entries_) out.push_back(e.info);
  return out;
}

const Lineup::Entry& Lineup::loaded(const std::string& plugin) const {
  if (const Entry* e = find(plugin)) return *e;
  std::vector<std::string> names;
  std::string list;
  for (const auto& e : entries_) {
    names.push_back(e.name);
    list += (list.empty() ? "" : ", ") + e.name;
  }
  const std::string hint = did_you_mean(closest_names(plugin, names));
  throw ParameterError("estimator '" + plugin + "' is not loaded (loaded: " + list + ")" + (hint.empty() ? "" : ": " + hint));
}

Parameters Lineup::load(const std::string& plugin, const std::vector<std::string>& assignments) {
  // The names of --plugin: a second one of a name would publish on the same topic.
  if (find(plugin) != nullptr) throw ParameterError("estimator '" + plugin + "' is named twice");
  estimator::EstimatorPtr trial = estimator::load_estimator(plugin);
  const estimator::Info info = trial->info();
  const Parameters parameters = estimator::assign_parameters({info}, assignments, window_s_).front();
  trial->configure(parameters);
  entries_.push_back({plugin, info, parameters});
  return parameters;
}

void Lineup::unload(const std::string& plugin) {
  loaded(plugin);
  if (entries_.size() == 1)
    throw ParameterError("estimator '" + plugin + "' is the only one loaded: load another before unloading it");
  std::erase_if(entries_, [&](const Entry& e) { return e.name == plugin; });
}

Parameters Lineup::set(const std::string& plugin, const std::string& name, const std::string& value) {
  // The assignment as --param would carry it, checked by the same function: the same refusal.
  const std::vector<Parameters> assigned = estimator::assign_parameters(infos(), {plugin + "." + name + "=" + value}, std::nullopt);
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (entries_[i].name != plugin) continue;
    Parameters merged = entries_[i].parameters;
    for (const auto& [k, v] : assigned[i]) merged[k] = v;
    estimator::load_estimator(plugin)->configure(merged);  // a spare instance: the value's own check
    entries_[i].parameters = merged;
    return merged;
  }
  return loaded(plugin).parameters;  // not reached: assign_parameters refused an unknown plugin
}

Lineup::Value Lineup::get(const std::string& plugin, const std::string& name) const {
  const Entry& e = loaded(plugin);
  for (const auto& spec : e.info.parameters) {
    if (spec.name != name) continue;
    const auto given = e.parameters.find(name);
    return {plugin, name, given != e.parameters.end() ? given->second : spec.default_value, spec.default_value};
  }
  // The refusal --param PLUGIN.NAME=... gets for a name the plugin does not declare.
  estimator::assign_parameters({e.info}, {plugin + "." + name + "=?"}, std::nullopt);
  throw ParameterError("'" + name + "': " + plugin + " has no such parameter");
}

std::vector<Lineup::Value> Lineup::dump(const std::string& plugin) const {
  const Entry& e = loaded(plugin);
  std::vector<Value> out;
  for (const auto& spec : e.info.parameters) out.push_back(get(plugin, spec.name));
  return out;
}

}  // namespace plumb::estimator_component
