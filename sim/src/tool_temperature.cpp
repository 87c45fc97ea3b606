// The tool's temperature in closed form: within each phase T = target + (T0 - target) exp(-(t - t0) / tau).
#include "plumb/sim/tool_temperature.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace plumb::sim {

TemperatureHistory::TemperatureHistory(const ToolTemperature& model, std::vector<double> starts,
                                       std::vector<bool> circulating)
    : model_(model), starts_(std::move(starts)), circulating_(std::move(circulating)) {
  start_temp_.resize(starts_.size());
  double temp = model_.start_c;
  for (std::size_t i = 0; i < starts_.size(); ++i) {
    start_temp_[i] = temp;
    if (i + 1 < starts_.size()) {
      const double target = circulating_[i] ? model_.circulating_c : model_.formation_c;
      const double tau = circulating_[i] ? model_.cool_tau_s : model_.heat_tau_s;
      temp = target + (temp - target) * std::exp(-(starts_[i + 1] - starts_[i]) / tau);
    }
  }
}

double TemperatureHistory::at(double t) const {
  if (starts_.empty() || t <= starts_.front()) return model_.start_c;
  const auto it = std::upper_bound(starts_.begin(), starts_.end(), t);
  const std::size_t i = static_cast<std::size_t>(it - starts_.begin()) - 1;
  const double target = circulating_[i] ? model_.circulating_c : model_.formation_c;
  const double tau = circulating_[i] ? model_.cool_tau_s : model_.heat_tau_s;
  return target + (start_temp_[i] - target) * std::exp(-(t - starts_[i]) / tau);
}

}  // namespace plumb::sim
