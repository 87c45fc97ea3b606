// The DDS side of plumb-display: readers of plumb/status and of every plumb/attitude/<estimator>
// and plumb/survey/<tool> topic discovery finds (they appear as estimators and surveys start),
// each message turned into the page's JSON and handed to the hub. Runs on one thread and never
// waits for a browser (the hub's outboxes take care of that).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "attitude_difference.hpp"
#include "hub.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::display_component {

class DdsFeed {
 public:
  // `differences`: every attitude taken goes through it (on the feed's thread), and its difference
  // from the tool's reference plugin goes to the page with the estimate.
  DdsFeed(transport::Participant& participant, Hub& hub, PluginDifferences& differences);
  ~DdsFeed();
  // Waits up to `timeout` for data, hands everything taken to the hub, and every half second
  // subscribes to topics that appeared. Returns how many messages it took.
  std::size_t poll(std::chrono::milliseconds timeout);
  std::size_t topics() const { return topics_.size(); }

  struct Stream;

 private:
  void discover();
  void wake();  // a reader's data callback (a vendor thread)

  transport::Participant& participant_;
  Hub& hub_;
  PluginDifferences& differences_;
  // Before the readers: a vendor thread may call wake() until the last reader is gone.
  std::mutex mutex_;
  std::condition_variable cv_;
  bool pending_ = false;
  std::vector<std::unique_ptr<Stream>> streams_;
  std::set<std::string> topics_;
  std::map<std::string, Stream*> discovered_streams_;  // attitudes and surveys by topic (owned by streams_)
  std::set<std::string> unwritten_;  // of those, topics whose last writer is gone
  std::chrono::steady_clock::time_point last_discovery_{};
};

}  // namespace plumb::display_component
