// Several configured estimators side by side on one sample stream: the loop that the estimator
// host, `plumb estimate` and `plumb compare` share. No DDS and no files here: callers feed
// samples and take the estimates through a sink.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "plumb/estimator/estimator.hpp"

namespace plumb::estimator {

class Runner {
 public:
  struct Slot {
    std::string name;  // the plugin's name; every estimate it makes carries it
    EstimatorPtr estimator;
    Parameters parameters;
    std::uint64_t estimates = 0;
    std::uint64_t invalid = 0;
    std::string last_reason;  // of the last invalid estimate: why a plugin that made none valid failed
  };
  // Called for every estimate, in the order the estimators made them.
  using Sink = std::function<void(const Slot& slot, Estimate& estimate)>;

  Runner() = default;
  void add(std::string name, EstimatorPtr estimator);

  // Gives each estimator its own parameters (one Parameters per estimator, in order; see
  // assign_parameters) and resets it. Throws ParameterError before anything runs.
  void configure(const std::vector<Parameters>& parameters);
  // --param KEY=VALUE assignments and an optional window, distributed by assign_parameters.
  void configure(const std::vector<std::string>& assignments, std::optional<double> window_s);
  // Back to the state right after configure (a new record, a new tool).
  void reset();

  void push(std::span<const Sample> samples, const Sink& sink);
  // End of the stream: every estimator reports what its open window holds.
  void flush(const Sink& sink);

  const std::vector<Slot>& slots() const { return slots_; }
  std::vector<Info> infos() const;
  // "estimates", "invalid" and the estimator's own counters, each as "<plugin>.<name>".
  std::vector<std::pair<std::string, std::uint64_t>> counters() const;
  // Names of the estimators that need gyros, for the warning when a stream carries none.
  std::vector<std::string> needing_gyro() const;

 private:
  void deliver(Slot& slot, std::vector<Estimate>& made, const Sink& sink);
  std::vector<Slot> slots_;
  std::vector<Estimate> made_;
};

}  // namespace plumb::estimator
