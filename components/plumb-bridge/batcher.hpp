// Groups checked samples into sensor batches: at most kMaxSamplesPerBatch each, and none held
// back longer than the flush interval (consumers see data at least every 50 ms at any rate).
#pragma once

#include <chrono>
#include <vector>

#include "plumb/core/sample.hpp"

namespace plumb::bridge_component {

class Batcher {
 public:
  using Clock = std::chrono::steady_clock;
  explicit Batcher(std::size_t max_samples = 32, std::chrono::milliseconds max_age = std::chrono::milliseconds(50))
      : max_samples_(max_samples), max_age_(max_age) {}

  // True when the batch is full and must be taken now.
  bool add(const Sample& s, Clock::time_point now) {
    if (pending_.empty()) first_at_ = now;
    pending_.push_back(s);
    return pending_.size() >= max_samples_;
  }
  // True when samples have waited for the flush interval.
  bool due(Clock::time_point now) const { return !pending_.empty() && now - first_at_ >= max_age_; }
  bool empty() const { return pending_.empty(); }
  std::vector<Sample> take() {
    std::vector<Sample> out;
    out.swap(pending_);
    return out;
  }

 private:
  std::size_t max_samples_;
  std::chrono::milliseconds max_age_;
  std::vector<Sample> pending_;
  Clock::time_point first_at_{};
};

}  // namespace plumb::bridge_component
