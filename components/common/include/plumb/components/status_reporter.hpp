// Every component's health on plumb/status: one reporter, so that all components say it alike
// (component, host, state, counters, last error) at the same period.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "plumb/transport/topic_names.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::components {

using CounterList = std::vector<std::pair<std::string, std::uint64_t>>;

std::string host_name();

// One status message; counters beyond the IDL bound are dropped (the first ones are kept). `name`:
// what the component was named on its command line (plumb-estimator --name), "" for none.
topics::ComponentStatus make_status(const std::string& component, const std::string& state, const CounterList& counters,
                                    const std::string& last_error, const std::string& name = "");

class StatusReporter {
 public:
  static constexpr std::chrono::milliseconds kLastWordsWait{1000};
  StatusReporter(transport::Participant& participant, std::string component, double period_s = 1.0,
                 const std::string& topic = transport::topic_names::kStatus);
  // The component's own name (plumb-estimator --name), sent with every report: `plumb status` shows
  // it beside the computer's.
  void set_name(std::string name) { name_ = std::move(name); }
  // The last report ("stopping", "finished", or "failed" before an exit) must reach the monitors
  // already matched: the reporter waits, at most kLastWordsWait, until every one of them has
  // acknowledged it before its writer goes (and the participant after it).
  ~StatusReporter();
  StatusReporter(StatusReporter&& other) noexcept;
  StatusReporter& operator=(StatusReporter&&) = delete;
  // Publishes now. The writer keeps the last report for monitors that join later
  // (transient-local), as long as the component runs.
  void publish(const std::string& state, const CounterList& counters, const std::string& last_error = "");
  // True once per period: the caller then gathers its counters and publishes.
  bool due();

 private:
  transport::Writer<topics::ComponentStatus> writer_;
  std::string component_;
  std::string name_;
  std::chrono::steady_clock::duration period_;
  std::chrono::steady_clock::time_point next_;
  bool owns_writer_ = true;  // false once moved from: nothing left to deliver
};

}  // namespace plumb::components
