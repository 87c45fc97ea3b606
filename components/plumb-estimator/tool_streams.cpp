#include "tool_streams.hpp"

namespace plumb::estimator_component {

void SequenceAccount::account(std::uint64_t seq) {
  if (paused) {
    paused = false;
    if (seq > next_seq) {
      ++silent_gaps;
      silent_lost += seq - next_seq;
    } else if (seq < next_seq) {
      ++source_restarts;
    }
  } else if (have_seq && seq != next_seq) {
    if (seq > next_seq) {
      ++gaps;
      lost += seq - next_seq;
    } else {
      ++backwards;
    }
  }
  have_seq = true;
  next_seq = seq + 1;
}

std::size_t new_run_start(std::span<const Sample> chunk, std::optional<double> last_t) {
  for (std::size_t i = 0; i < chunk.size(); ++i) {
    if (last_t && chunk[i].t < *last_t) return i;
    last_t = chunk[i].t;
  }
  return chunk.size();
}

void SequenceAccount::clock(double first_t, double last_t) {
  if (latest_t && first_t < *latest_t) restart();
  latest_t = last_t;
}

SequenceAccount* ToolStreams::route(const std::string& tool_id) {
  if (!selected_.empty() && tool_id != selected_) {
    ++other_tool_batches_;
    return nullptr;
  }
  return &streams_[tool_id];
}

void ToolStreams::restart_all() {
  for (auto& [tool, account] : streams_) account.restart();
}

std::uint64_t ToolStreams::gaps() const {
  std::uint64_t n = 0;
  for (const auto& [tool, a] : streams_) n += a.gaps;
  return n;
}

std::uint64_t ToolStreams::lost() const {
  std::uint64_t n = 0;
  for (const auto& [tool, a] : streams_) n += a.lost;
  return n;
}

std::uint64_t ToolStreams::silent_gaps() const {
  std::uint64_t n = 0;
  for (const auto& [tool, a] : streams_) n += a.silent_gaps;
  return n;
}

std::uint64_t ToolStreams::silent_lost() const {
  std::uint64_t n = 0;
  for (const auto& [tool, a] : streams_) n += a.silent_lost;
  return n;
}

std::uint64_t ToolStreams::source_restarts() const {
  std::uint64_t n = 0;
  for (const auto& [tool, a] : streams_) n += a.source_restarts;
  return n;
}

std::uint64_t ToolStreams::backwards() const {
  std::uint64_t n = 0;
  for (const auto& [tool, a] : streams_) n += a.backwards;
  return n;
}

}  // namespace plumb::estimator_component
