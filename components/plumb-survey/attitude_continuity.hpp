// Attitude windows that never arrived: an estimator host killed and restarted loses the windows it
// had in progress, a link outage longer than the writer's history loses some. Each window should
// start where the previous one ended; a jump of at least half a window is counted as that many
// windows missing, so that what a fault cost shows on plumb/status and in the log.
// Pure logic (no DDS).
#pragma once

#include <cstdint>
#include <string>

namespace plumb::survey_component {

class AttitudeContinuity {
 public:
  // One window (times in s). Returns the windows missing before it (0 when it follows on).
  std::uint64_t add(double t_start, double t_end);
  std::uint64_t gaps() const { return gaps_; }
  std::uint64_t windows_missing() const { return missing_; }
  std::uint64_t out_of_order() const { return out_of_order_; }
  // "attitude gap of 2.5 s before the window starting at t = 103.0 s (5 windows missing)".
  const std::string& last_note() const { return note_; }

 private:
  bool have_ = false;
  double last_start_ = 0, last_end_ = 0, length_ = 0;
  std::uint64_t gaps_ = 0, missing_ = 0, out_of_order_ = 0;
  std::string note_;
};

}  // namespace plumb::survey_component
