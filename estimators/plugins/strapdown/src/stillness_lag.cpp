#include "plumb/strapdown/stillness_lag.hpp"

#include <utility>

namespace plumb::strapdown {

void StillnessLag::reset(double lag_s) {
  queue_.clear();
  lag_s_ = lag_s;
  newest_still_ = false;
}

void StillnessLag::push(const InputReading& reading, const StillnessState& decision) {
  Entry entry{reading, decision};
  // (The end moves back, or the stop vanishes: either way this reading no longer ends it.)
  if (newest_still_ && !decision.still && take_back(reading.t, decision.ended)) entry.still.ended = false;
  newest_still_ = decision.still;
  queue_.push_back(entry);
}

// The stop ended at end_t: the readings still waiting that lie less than lag_s before it were not
// still. The first of them becomes the stop's end, unless it is the stop's start (then the stop
// never reaches the filter). Whether any reading was taken back.
bool StillnessLag::take_back(double end_t, bool ended) {
  std::size_t first = queue_.size();
  while (first > 0 && queue_[first - 1].still.still && queue_[first - 1].reading.t > end_t - lag_s_) --first;
  if (first == queue_.size()) return false;
  bool vanished = false;
  for (std::size_t i = first; i < queue_.size(); ++i) {
    StillnessState& s = queue_[i].still;
    vanished = vanished || s.started;
    s = StillnessState();
  }
  if (!vanished) queue_[first].still.ended = ended;
  return true;
}

std::optional<StillnessLag::Entry> StillnessLag::pop_ready() {
  if (queue_.empty() || queue_.back().reading.t - queue_.front().reading.t < lag_s_) return std::nullopt;
  return pop_any();
}

std::optional<StillnessLag::Entry> StillnessLag::pop_any() {
  if (queue_.empty()) return std::nullopt;
  Entry entry = std::move(queue_.front());
  queue_.pop_front();
  return entry;
}

}  // namespace plumb::strapdown
