#include "plumb/estimator/runner.hpp"

#include <limits>
#include <stdexcept>

#include "plumb/estimator/assignments.hpp"

namespace plumb::estimator {
namespace {

// What an estimate did not measure is NaN on every topic and in every file, never a number that
// looks measured (an inclination of 4e-16, a sigma of 0, a dip of 90 from a window that could not
// be used). The plugins fill invalid estimates with whatever their formulas gave and report an
// unknown sigma as 0; every host receives estimates through here.
void mark_unmeasured(Estimate& e) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (!e.valid) {
    e.inclination_deg = e.azimuth_deg = e.gravity_toolface_deg = e.magnetic_toolface_deg = nan;
    e.inclination_sd_deg = e.azimuth_sd_deg = e.toolface_sd_deg = nan;
    e.dip_deg = e.total_g = e.total_b = nan;
    // A navigator before alignment has no position or velocity either.
    if (e.navigation) {
      for (auto* a : {&e.navigation->position_m, &e.navigation->velocity_mps, &e.navigation->position_sd_m,
                      &e.navigation->velocity_sd_mps})
        a->fill(nan);
    }
    return;
  }
  if (!e.azimuth_valid) e.azimuth_deg = e.azimuth_sd_deg = nan;
  if (!e.toolface_valid) e.gravity_toolface_deg = e.toolface_sd_deg = nan;
  for (double* sd : {&e.inclination_sd_deg, &e.azimuth_sd_deg, &e.toolface_sd_deg})
    if (*sd == 0) *sd = nan;  // the plugins' "0 when not estimated"
}

}  // namespace

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
  std::vector<ParameterOrigins> origins;
  const std::vector<Parameters> parameters = assign_parameters(infos(), assignments, window_s, &origins);
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    slots_[i].parameters = parameters[i];
    try {
      slots_[i].estimator->configure(slots_[i].parameters);
    } catch (const ParameterError& e) {
      throw ParameterError(located(e.what(), origins[i]));  // a file's bad value: its file and line
    }
  }
}

void Runner::reset() {
  for (auto& s : slots_) s.estimator->configure(s.parameters);
}

void Runner::deliver(Slot& slot, std::vector<Estimate>& made, const Sink& sink) {
  for (auto& e : made) {
    e.estimator = slot.name;
    mark_unmeasured(e);
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

const Runner::Slot* Runner::find(const std::string& name) const {
  for (const auto& s : slots_)
    if (s.name == name) return &s;
  return nullptr;
}

bool Runner::remove(const std::string& name, const Sink& sink) {
  for (auto it = slots_.begin(); it != slots_.end(); ++it) {
    if (it->name != name) continue;
    it->estimator->flush(made_);
    deliver(*it, made_, sink);
    slots_.erase(it);
    return true;
  }
  return false;
}

void Runner::reconfigure(const std::string& name, const Parameters& parameters, const Sink& sink) {
  for (auto& s : slots_) {
    if (s.name != name) continue;
    s.estimator->flush(made_);
    deliver(s, made_, sink);
    s.parameters = parameters;
    s.estimator->configure(s.parameters);
    return;
  }
  throw std::out_of_range("no estimator '" + name + "' in this runner");
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

std::vector<std::string> Runner::take_notices() {
  std::vector<std::string> out;
  for (auto& s : slots_)
    for (auto& text : s.estimator->take_notices()) out.push_back(s.name + ": " + text);
  return out;
}

std::vector<std::string> Runner::needing_gyro() const {
  std::vector<std::string> out;
  for (const auto& s : slots_)
    if (s.estimator->info().uses_gyro) out.push_back(s.name);
  return out;
}

}  // namespace plumb::estimator
