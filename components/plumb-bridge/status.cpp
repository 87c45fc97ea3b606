#include "status.hpp"

#include <unistd.h>

#include <chrono>

namespace plumb::bridge {

std::string host_name() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

topics::ComponentStatus make_status(const Counters& counters, const std::string& state, const std::string& last_error,
                                    const std::string& component) {
  topics::ComponentStatus s;
  s.component = component.substr(0, topics::kComponentMax);
  s.host = host_name().substr(0, topics::kHostMax);
  s.state = state.substr(0, topics::kStateMax);
  s.stamp_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
                   .count();
  for (const auto& [name, value] : counters.named()) {
    if (s.counters.size() >= topics::kMaxCountersPerStatus) break;
    s.counters.push_back({name.substr(0, topics::kNameMax), value});
  }
  s.last_error = last_error.substr(0, topics::kErrorMax);
  return s;
}

}  // namespace plumb::bridge
