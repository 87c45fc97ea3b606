#include "plumb/estimator/assignments.hpp"

#include "plumb/core/edit_distance.hpp"

namespace plumb::estimator {

bool declares_parameter(const Info& info, const std::string& name) {
  for (const auto& spec : info.parameters)
    if (spec.name == name) return true;
  return false;
}

std::string with_origin(const std::string& origin, const std::string& assignment) {
  return origin + kOriginSeparator + assignment;
}

namespace {

// ": did you mean X?" or "".
std::string hint(const std::string& name, const std::vector<std::string>& candidates) {
  const std::string text = did_you_mean(closest_names(name, candidates));
  return text.empty() ? text : ": " + text;
}

}  // namespace

std::vector<Parameters> assign_parameters(const std::vector<Info>& estimators, const std::vector<std::string>& assignments,
                                          std::optional<double> window_s, std::vector<ParameterOrigins>* origins) {
  std::vector<Parameters> out(estimators.size());
  if (origins != nullptr) origins->assign(estimators.size(), {});
  for (std::size_t i = 0; i < estimators.size(); ++i) {
    if (window_s && declares_parameter(estimators[i], "window")) out[i]["window"] = std::to_string(*window_s);
  }
  for (const auto& written : assignments) {
    // Messages start with where the assignment was written: "--param 'a=1'" or "FILE:LINE".
    const auto separator = written.find(kOriginSeparator);
    const std::string kv = separator == std::string::npos ? written : written.substr(separator + 1);
    const std::string where = separator == std::string::npos ? "--param '" + kv + "'" : written.substr(0, separator);
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw ParameterError(where + " is not [PLUGIN.]KEY=VALUE");
    std::string key = kv.substr(0, eq);
    std::string only;  // PLUGIN.KEY: that plugin alone
    if (const auto dot = key.find('.'); dot != std::string::npos) {
      only = key.substr(0, dot);
      key = key.substr(dot + 1);
      bool selected = false;
      std::vector<std::string> names;
      for (const auto& info : estimators) {
        selected = selected || info.name == only;
        names.push_back(info.name);
      }
      if (!selected) throw ParameterError(where + ": estimator '" + only + "' is not selected" + hint(only, names));
    }
    bool used = false;
    for (std::size_t i = 0; i < estimators.size(); ++i) {
      if ((!only.empty() && estimators[i].name != only) || !declares_parameter(estimators[i], key)) continue;
      out[i][key] = kv.substr(eq + 1);
      if (origins != nullptr && separator != std::string::npos) (*origins)[i][key] = where;
      used = true;
    }
    if (!used) {
      std::vector<std::string> declared;
      for (const auto& info : estimators)
        if (only.empty() || info.name == only)
          for (const auto& spec : info.parameters) declared.push_back(spec.name);
      throw ParameterError((separator == std::string::npos ? "--param '" + key + "'" : where + ": '" + key + "'") + ": " +
                           (only.empty() ? "no selected estimator has that parameter" : only + " has no such parameter") +
                           hint(key, declared) + " (see plumb plugins -v)");
    }
  }
  return out;
}

std::string located(const std::string& message, const ParameterOrigins& origins) {
  for (const auto& [key, origin] : origins)
    if (message.find("'" + key + "'") != std::string::npos) return origin + ": " + message;
  return message;
}

}  // namespace plumb::estimator
