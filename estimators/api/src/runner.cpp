#include "plumb/estimator/runner.hpp"

#include "plumb/estimator/assignments.hpp"

namespace plumb::estimator {

void Runner::add(std::string name, EstimatorPtr estimator) {
  slots_.push_back({std::move(name), std::move(estimator), {}, 0, 0, {}});
}

std::vector<Info> Runner::infos() const {
  std::vector<Info> out;
  for (const auto& s : slots_) out.push_back(s.estimator->info());
  return out;
}

void Runner::configure(const std::vector<Parameters>& parameters) {
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    slots_[i].parameters = i < parameters.size() ? parameters[i] : Parameters{};
    slots_[i].estimator->configure(slots_[i].parameters);
  }
}

void Runner::configure(const std::vector<std::string>& assignments, std::optional<double> window_s) {
  configure(assign_parameters(infos(), assignments, window_s));
}

void Runner::reset() {
  for (auto& s : slots_) s.estimator->configure(s.parameters);
}

void Runner::deliver(Slot& slot, std::vector<Estimate>& made, const Sink& sink) {
  for (auto& e : made) {
    e.estimator = slot.name;
    ++slot.estimates;
    if (!e.valid) {
      ++slot.invalid;
      slot.last_reason = e.reason;
    }
    if (sink) sink(slot, e);
  }
  made.clear();
}

void Runner::push(std::span<const Sample> samples, const Sink& sink) {
  for (auto& s : slots_) {
    s.estimator->push(samples, made_);
    deliver(s, made_, sink);
  }
}

void Runner::flush(const Sink& sink) {
  for (auto& s : slots_) {
    s.estimator->flush(made_);
    deliver(s, made_, sink);
  }
}

std::vector<std::pair<std::string, std::uint64_t>> Runner::counters() const {
  std::vector<std::pair<std::string, std::uint64_t>> out;
  for (const auto& s : slots_) {
    out.emplace_back(s.name + ".estimates", s.estimates);
    out.emplace_back(s.name + ".invalid", s.invalid);
    for (const auto& [reason, n] : s.estimator->counters()) out.emplace_back(s.name + "." + reason, n);
  }
  return out;
}

std::vector<std::string> Runner::needing_gyro() const {
  std::vector<std::string> out;
  for (const auto& s : slots_)
    if (s.estimator->info().uses_gyro) out.push_back(s.name);
  return out;
}

}  // namespace plumb::estimator
