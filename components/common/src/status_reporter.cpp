#include "plumb/components/status_reporter.hpp"

#include <unistd.h>

#include <utility>

#include "plumb/components/convert.hpp"

namespace plumb::components {

std::string host_name() {
  char name[256] = {};
  return ::gethostname(name, sizeof name - 1) == 0 ? name : "unknown";
}

topics::ComponentStatus make_status(const std::string& component, const std::string& state, const CounterList& counters,
                                    const std::string& last_error, const std::string& name) {
  topics::ComponentStatus s;
  s.component = bounded(component, topics::ComponentStatus::kComponentMax);
  s.host = bounded(host_name(), topics::ComponentStatus::kHostMax);
  s.state = bounded(state, topics::ComponentStatus::kStateMax);
  s.stamp_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
                   .count();
  for (const auto& [name, value] : counters) {
    if (s.counters.size() >= topics::ComponentStatus::kCountersMax) break;
    s.counters.push_back({bounded(name, topics::Counter::kNameMax), value});
  }
  s.last_error = bounded(last_error, topics::ComponentStatus::kLastErrorMax);
  s.name = bounded(name, topics::ComponentStatus::kNameMax);
  return s;
}

StatusReporter::StatusReporter(transport::Participant& participant, std::string component, double period_s,
                               const std::string& topic)
    : writer_(transport::make_writer<topics::ComponentStatus>(participant, topic, transport::Qos::status())),
      component_(std::move(component)),
      period_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(period_s))),
      next_(std::chrono::steady_clock::now() + period_) {}

void StatusReporter::publish(const std::string& state, const CounterList& counters, const std::string& last_error) {
  writer_.write(make_status(component_, state, counters, last_error, name_));
}

// The last words: the participant goes right after the reporter, and would take them along before
// a matched monitor got them. Bounded: a monitor killed a moment ago is still matched until its
// lease ends, and never answers. Nothing to wait for when every report was acknowledged long ago.
StatusReporter::StatusReporter(StatusReporter&& other) noexcept
    : writer_(std::move(other.writer_)),
      component_(std::move(other.component_)),
      name_(std::move(other.name_)),
      period_(other.period_),
      next_(other.next_),
      owns_writer_(std::exchange(other.owns_writer_, false)) {}

StatusReporter::~StatusReporter() {
  if (!owns_writer_) return;
  try {
    writer_.wait_for_acknowledgments(kLastWordsWait);
  } catch (...) {  // a vendor error at exit: nothing more can be done for the monitors
  }
}

bool StatusReporter::due() {
  const auto now = std::chrono::steady_clock::now();
  if (now < next_) return false;
  next_ += period_;
  if (next_ < now) next_ = now + period_;
  return true;
}

}  // namespace plumb::components
