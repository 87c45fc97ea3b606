// Between the DDS reader and the browsers: the latest state (for browsers that join later) and one
// outbox per browser. The reader only ever appends to outboxes under a short lock; each browser's
// own sender thread empties its outbox at its own pace. A browser that is slow or gone therefore
// never blocks the reader: its outbox keeps the latest few estimates per tool and estimator, drops
// the older ones and counts them.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace plumb::display_component {

using Text = std::shared_ptr<const std::string>;

// One point of an estimate's history (what the page's charts draw).
struct HistoryPoint {
  double rx_ms = 0;  // when the display received it, ms since the epoch
  double inclination = 0, azimuth = 0, toolface = 0, rpm = 0;
  std::uint32_t flags = 0;
};

struct HubOptions {
  // Estimates kept per tool and estimator for a browser that lags: two seconds of a 30 Hz estimator,
  // and more than any estimator sends between two frames (30 a second).
  std::size_t backlog = 64;
  std::size_t max_stations = 10000;         // survey stations kept (and sent to a browser that joins)
  double history_s = 600;                   // history sent to a browser that joins
  double history_step_s = 0.25;             // at most one history point per this many seconds and stream
  std::chrono::milliseconds min_gap{33};    // at most one frame per this interval and browser (30/s)
  std::chrono::milliseconds heartbeat{1000};  // a frame at least this often, so that pages see a dead link
};

// What one browser has not been sent yet.
class Outbox {
 public:
  // The next frame (JSON text) once something is due, the throttle allows it, or a heartbeat is
  // due; nullopt once closed.
  std::optional<std::string> next();
  // Wakes next() for good (the browser left).
  void close();
  std::uint64_t dropped() const;

 private:
  friend class Hub;
  explicit Outbox(const HubOptions& options) : options_(options) {}
  bool pending() const { return !attitudes_.empty() || !states_.empty() || !stations_.empty() || !gone_.empty() || hello_; }

  const HubOptions options_;  // a copy: a sender thread may hold its outbox a moment longer than the hub lives
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  std::map<std::string, std::deque<Text>> attitudes_;  // by tool/estimator, oldest first
  // States of which only the latest counts, by kind (the frame's list: "status", "clearance",
  // "depth") and key (component@host, tool/offset well, tool).
  std::map<std::string, std::map<std::string, Text>> states_;
  std::deque<Text> stations_;
  std::set<std::string> gone_;  // estimate streams (tool/estimator) whose cards leave the page
  Text hello_;  // snapshot for a browser that just joined: history and server settings
  bool closed_ = false;
  std::uint64_t dropped_ = 0, frames_ = 0;
  std::chrono::steady_clock::time_point last_sent_{};
};

struct HubStats {
  std::size_t browsers = 0;
  std::uint64_t browsers_total = 0;  // joined since the start
  std::uint64_t attitudes = 0, statuses = 0, stations = 0, clearances = 0, depths = 0;
  std::uint64_t dropped = 0;  // estimates dropped for slow browsers, over all browsers ever
};

class Hub {
 public:
  explicit Hub(HubOptions options = {});

  // Producer side (the DDS thread). `key` names the stream: tool/estimator, component@host,
  // tool#station, tool/offset well.
  void attitude(const std::string& key, const std::string& json, const HistoryPoint& point);
  // The stream is no more (its estimator's topic has no writer): its latest estimate and history are
  // forgotten and the pages drop its card (the frame's "gone" list).
  void forget_attitude(const std::string& key);
  void status(const std::string& key, const std::string& json);
  void station(const std::string& key, const std::string& json);
  // The newest station's clearance against one offset well (the page shows the nearest).
  void clearance(const std::string& key, const std::string& json);
  // A tool's newest measured depth.
  void depth(const std::string& key, const std::string& json);

  // Consumer side (a browser's sender thread): an outbox filled with the current state.
  std::shared_ptr<Outbox> join();
  void leave(const std::shared_ptr<Outbox>& outbox);

  HubStats stats() const;
  const HubOptions& options() const { return options_; }

 private:
  std::string hello_json() const;  // under mutex_
  // A state of which only the latest counts (a status, a clearance, a depth): kept for browsers
  // that join later, and replacing the one each browser has not been sent yet.
  void latest(const std::string& kind, const std::string& key, const std::string& json);

  const HubOptions options_;
  mutable std::mutex mutex_;
  std::vector<std::shared_ptr<Outbox>> outboxes_;
  std::map<std::string, Text> latest_attitude_;
  std::map<std::string, std::deque<HistoryPoint>> history_;
  std::map<std::string, std::map<std::string, Text>> states_;  // by kind and key, as Outbox::states_
  std::map<std::string, Text> stations_;  // by tool#index: a station sent again replaces itself
  std::deque<std::string> station_order_;
  HubStats stats_;
  std::uint64_t dropped_by_gone_ = 0;  // drops of browsers that left
};

}  // namespace plumb::display_component
