// Survey stations from an attitude stream and the rig's measured depth: a station is the first
// valid attitude window that lies wholly inside a period where the measured depth stood still (a
// pipe connection or a survey stop), one per stop. Without a depth input, a stop is a run of valid,
// non-rotating windows, and a pipe tally gives its depth: start + joint lengths, one joint per stop,
// plus corrections.
//
// Time stamps of attitude windows and depth reports are on the same clock (the rig's and the
// sensors' clock, seconds). The detector is fed in any interleaving; it decides on a window once a
// depth report at or after the window's end has arrived (or at flush()).
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "plumb/core/estimate.hpp"
#include "plumb/survey/survey.hpp"

namespace plumb::survey {

struct DepthReport {
  double t_s = 0;
  double depth_m = 0;
  double sd_m = 0;
  bool moving = false;    // the rig says the string moved (DEPTH_MOVING)
};

// Pipe tally: depth of stop k (0-based) = start + sum of the first k joint lengths + correction k.
// Joints past the list have the last length.
struct PipeTally {
  double start_md_m = 0;
  std::vector<double> joint_lengths_m;  // at least one
  std::vector<double> corrections_m;    // optional, per stop
  double sd_m = 0;                      // uncertainty of a tally depth
  double depth_at(std::size_t stop) const;
};

struct DetectorOptions {
  double still_tolerance_m = 0.02;   // depth spread within a window that still counts as standing
  double new_station_m = 0.1;        // a stop closer than this to the last station is the same place
  double max_depth_gap_s = 2.0;      // a window needs depth reports this close to its start and end
  double min_still_s = 5.0;          // the depth must stand this long before a window's end (short
                                     // windows, e.g. a navigator's 1 s rows, at the very end of a
                                     // slow-down would otherwise pass)
  double depth_history_s = 600;      // depth kept for windows still to come (longer windows see no depth)
  std::optional<PipeTally> tally;    // no depth input: stops from the attitude stream, depth from the tally
};

struct DetectorCounters {
  std::uint64_t windows = 0;            // attitude windows received
  std::uint64_t invalid_windows = 0;    // inclination not valid
  std::uint64_t rotating_windows = 0;   // valid but turning (counted; only the tally mode skips them)
  std::uint64_t moving_windows = 0;     // depth changed within the window
  std::uint64_t no_depth_windows = 0;   // no depth report near the window
  std::uint64_t same_stop_windows = 0;  // further still windows of a stop that has its station
  std::uint64_t repeat_stops = 0;       // a new stop at the last station's depth (a resurvey): not a station
  std::uint64_t old_windows = 0;        // at or before the last station (replayed after a restart)
  std::uint64_t stations = 0;
};

class StationDetector {
 public:
  using Sink = std::function<void(const Station&)>;
  // `note` (optional) hears the events that are not stations but deserve a line (a repeat stop).
  StationDetector(DetectorOptions options, Sink sink, std::function<void(const std::string&)> note = {});
  // Resume after a restart: the last station already in the survey.
  void resume(double last_station_t_s, double last_station_md_m, std::size_t stations_so_far);
  void add_depth(const DepthReport& d);
  void add_attitude(const Estimate& e, const std::string& tool_id);
  // Decides every pending window with the depth reports there are (end of a file, long silence).
  void flush();
  const DetectorCounters& counters() const { return counters_; }

 private:
  struct Pending {
    Estimate e;
    std::string tool_id;
  };
  void process_ready(bool all);
  void decide(const Pending& p);
  void take(const Pending& p, double md, double md_sd);
  void prune();
  bool moved_since(double until) const;  // the depth left the last station's between it and `until`

  DetectorOptions options_;
  Sink sink_;
  std::function<void(const std::string&)> note_;
  std::deque<DepthReport> depth_;   // in time order
  std::deque<Pending> pending_;     // in window-end order
  DetectorCounters counters_;
  std::optional<double> last_md_;
  double last_t_ = -1e300;
  double last_azimuth_ = 0;  // of the last station: for one whose azimuth was not measured
  bool in_stop_ = false;            // tally mode: inside a run of still windows
  std::size_t stops_ = 0;           // tally mode: stops seen
};

}  // namespace plumb::survey
