// Several tools on one sensor topic: each tool id is its own stream, with its own sequence
// accounting, so that one tool's sequence numbers never count as the other's losses and no
// estimate ever mixes two tools. With a selected tool id, only that tool is a stream and the
// batches of every other tool are counted. Pure logic (no DDS), tested directly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>

#include "plumb/core/sample.hpp"

namespace plumb::estimator_component {

// The sequence numbers of one tool's samples: gaps (and the samples they lost) and steps back.
// Across a pause (the stream went silent: a link down, a bridge restarted) the numbers are kept
// apart: a jump forward is what the pause cost (silent_lost, in silent_gaps), a step back is a
// source that started again from its beginning (source_restarts), neither a fault of the stream.
struct SequenceAccount {
  bool have_seq = false;
  bool paused = false;
  std::uint64_t next_seq = 0;
  std::uint64_t gaps = 0, lost = 0, backwards = 0;
  std::uint64_t silent_gaps = 0, silent_lost = 0, source_restarts = 0;
  void account(std::uint64_t seq);
  // After a pause: the next sequence number is not expected to follow the last one.
  void restart() { paused = have_seq; }
  // A batch's first and last sample times, before its sequence numbers are accounted. A clock that
  // went back is a source started again (a second plumb-sim run, a replay from its start), as after
  // a pause: its sequence starting over is no step back.
  void clock(double first_t, double last_t);
  std::optional<double> latest_t;
};

// Where a tool's chunk of samples starts a new run: the index of the first sample whose time is
// earlier than the one before it (`last_t`: the time of the tool's last sample before the chunk),
// or chunk.size() when time never goes back. A source started again (a second plumb-sim run, a
// replay from its beginning) restarts its clock; its samples would otherwise be refused by every
// plugin as going back in time, and nothing more would be estimated for that tool.
std::size_t new_run_start(std::span<const Sample> chunk, std::optional<double> last_t);

class ToolStreams {
 public:
  // selected: "" for one stream per tool id seen; otherwise only that tool.
  explicit ToolStreams(std::string selected = {}) : selected_(std::move(selected)) {}
  // The account of the stream `tool_id` belongs to, created on first sight; nullptr when another
  // tool than the selected one (counted in other_tool_batches).
  SequenceAccount* route(const std::string& tool_id);
  void restart_all();
  const std::map<std::string, SequenceAccount>& streams() const { return streams_; }
  std::uint64_t other_tool_batches() const { return other_tool_batches_; }
  // Totals over the tools.
  std::uint64_t gaps() const;
  std::uint64_t lost() const;
  std::uint64_t backwards() const;
  std::uint64_t silent_gaps() const;
  std::uint64_t silent_lost() const;
  std::uint64_t source_restarts() const;

 private:
  std::string selected_;
  std::map<std::string, SequenceAccount> streams_;
  std::uint64_t other_tool_batches_ = 0;
};

}  // namespace plumb::estimator_component
