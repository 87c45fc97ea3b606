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

// Contract: a Runner is the estimators' contract gathered in one object. No call blocks (each runs
// its estimators to completion on the caller's thread; the sink runs there too, inside push and
// flush). A Runner is not thread-safe: one thread at a time per Runner, and every call on it from
// that thread, the sink included (the sink must not call back into the same Runner). Separate
// Runners share nothing and may run on separate threads (the estimator host keeps one per tool, all
// on its main thread). Allocation is stated per call.
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
  // Adds an estimator (loaded, not yet configured); configure before the first push.
  //   allocates: yes (a slot).
  void add(std::string name, EstimatorPtr estimator);

  // Gives each estimator its own parameters (one Parameters per estimator, in order; see
  // assign_parameters) and resets it. Throws ParameterError before anything runs.
  //   allocates: yes (each estimator's configure).
  void configure(const std::vector<Parameters>& parameters);
  // --param KEY=VALUE assignments and an optional window, distributed by assign_parameters.
  //   allocates: yes.
  void configure(const std::vector<std::string>& assignments, std::optional<double> window_s);
  // Back to the state right after configure (a new record, a new tool): each estimator is
  // configured again with its parameters. allocates: yes.
  void reset();

  // Each estimator in turn takes the samples; its estimates go to the sink, named after its slot,
  // before the next estimator runs.
  //   allocates: as Estimator::push; the Runner keeps one vector of estimates for all its
  //     estimators, so its capacity is reused from call to call.
  void push(std::span<const Sample> samples, const Sink& sink);
  // End of the stream: every estimator reports what its open window holds.
  //   allocates: as Estimator::flush.
  void flush(const Sink& sink);

  // Changes while samples flow (the estimator host's `plumb component` and `plumb param`): each
  // touches one slot and leaves every other slot's state, open window and counters as they were.
  // The slot named `name`, or nullptr. allocates: no.
  const Slot* find(const std::string& name) const;
  // Ends the slot's open window (its estimate goes to the sink), then removes the slot; false when
  // no slot has that name. allocates: as Estimator::flush.
  bool remove(const std::string& name, const Sink& sink);
  // Ends the slot's open window (its estimate goes to the sink), then configures the slot's
  // estimator with `parameters`, so they apply from its next window. Throws ParameterError as
  // Estimator::configure (validate on a spare instance first: the slot's state is already reset),
  // std::out_of_range for an unknown name. allocates: yes.
  void reconfigure(const std::string& name, const Parameters& parameters, const Sink& sink);

  //   allocates: no (a reference, valid until the next add).
  const std::vector<Slot>& slots() const { return slots_; }
  //   allocates: yes (infos(), counters() and needing_gyro() build their answer).
  std::vector<Info> infos() const;
  // "estimates", "invalid" and the estimator's own counters, each as "<plugin>.<name>".
  std::vector<std::pair<std::string, std::uint64_t>> counters() const;
  // Every estimator's notices since the last call (Estimator::take_notices), as "<plugin>: <text>".
  std::vector<std::string> take_notices();
  // Names of the estimators that need gyros, for the warning when a stream carries none.
  std::vector<std::string> needing_gyro() const;

 private:
  void deliver(Slot& slot, std::vector<Estimate>& made, const Sink& sink);
  std::vector<Slot> slots_;
  std::vector<Estimate> made_;
};

}  // namespace plumb::estimator
