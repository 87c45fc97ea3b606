#include "plumb/estimator/assignments.hpp"

namespace plumb::estimator {

bool declares_parameter(const Info& info, const std::string& name) {
  for (const auto& spec : info.parameters)
    if (spec.name == name) return true;
  return false;
}

std::vector<Parameters> assign_parameters(const std::vector<Info>& estimators, const std::vector<std::string>& assignments,
                                          std::optional<double> window_s) {
  std::vector<Parameters> out(estimators.size());
  for (std::size_t i = 0; i < estimators.size(); ++i) {
    if (window_s && declares_parameter(estimators[i], "window")) out[i]["window"] = std::to_string(*window_s);
  }
  for (const auto& kv : assignments) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw ParameterError("--param '" + kv + "' is not [PLUGIN.]KEY=VALUE");
    std::string key = kv.substr(0, eq);
    std::string only;  // PLUGIN.KEY: that plugin alone
    if (const auto dot = key.find('.'); dot != std::string::npos) {
      only = key.substr(0, dot);
      key = key.substr(dot + 1);
      bool selected = false;
      for (const auto& info : estimators) selected = selected || info.name == only;
      if (!selected) throw ParameterError("--param '" + kv + "': estimator '" + only + "' is not selected");
    }
    bool used = false;
    for (std::size_t i = 0; i < estimators.size(); ++i) {
      if ((!only.empty() && estimators[i].name != only) || !declares_parameter(estimators[i], key)) continue;
      out[i][key] = kv.substr(eq + 1);
      used = true;
    }
    if (!used)
      throw ParameterError("--param '" + key + "': " + (only.empty() ? "no selected estimator has" : only + " has no") +
                           " that parameter (see plumb plugins -v)");
  }
  return out;
}

}  // namespace plumb::estimator
