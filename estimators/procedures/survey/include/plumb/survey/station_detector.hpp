// Survey stations from an attitude stream and the rig's measured depth: a station is every valid
// attitude window that lies wholly inside a period where the measured depth stood still (a pipe
// connection or a survey stop), combined into one (stop_combiner.hpp), one per stop. The depth
// stands still when its reports stay within a tolerance that follows their noise: stated (the depth
// topic's sigma, --depth-sd) or measured from the reports' second differences (DepthNoiseFloor).
// Without a depth input, a stop is a run of valid, non-rotating windows, and a pipe tally gives its
// depth: start + joint lengths, one joint per stop, plus corrections.
//
// Time stamps of attitude windows and depth reports are on the same clock (the rig's and the
// sensors' clock, seconds). The detector is fed in any interleaving; it decides on a window once a
// depth report at or after the window's end has arrived (or at flush()).
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "plumb/core/depth_noise.hpp"
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
  double still_tolerance_m = 0.02;   // depth spread within a window that still counts as standing,
                                     // at least: kStillSigmas depth sigmas when the depth is noisier
  double depth_sd_m = -1;            // sigma of one depth report; < 0: the reports' own, or measured
  bool whole_stop = true;            // false: the first valid window of a stop is its station
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
  std::uint64_t combined_windows = 0;   // windows that went into the stations
  std::map<std::string, std::uint64_t> invalid_reasons;  // invalid windows by the estimator's reason
};

// How many depth sigmas the reports of a standing string may spread: the range of 60 reports of
// white noise stays below it 99.9 % of the time.
inline constexpr double kStillSigmas = 6.5;
// A standing depth also shows no rate: fitted over a span long enough to tell this slow a drilling
// from standing by 5 sigma (between these bounds), a rate above 2.5 sigma (and above the tolerance
// over the span) is motion.
inline constexpr double kSlowestDrillingMps = 0.01;
inline constexpr double kMinSlopeSpanS = 10;
inline constexpr double kMaxSlopeSpanS = 30;

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
  // A stop whose station waits for the depth to move (or for flush()).
  bool stop_open() const { return stop_.has_value(); }
  // The depth spread a standing string may show, m, and the depth sigma behind it (NaN: unknown).
  double still_tolerance_m() const;
  double depth_sd_m() const;

 private:
  struct Pending {
    Estimate e;
    std::string tool_id;
  };
  struct OpenStop {
    std::vector<Estimate> windows;
    std::string tool_id;
    double md = 0;                 // the first window's median depth: what later windows must match
    std::vector<double> depths;    // every report inside the windows' spans
    double md_sd = 0;
  };
  void process_ready(bool all);
  void decide(const Pending& p);
  void decide_with_depth(const Pending& p);
  void take(const std::vector<Estimate>& windows, const std::string& tool_id, double md, double md_sd);
  void close_stop();
  void prune();
  bool moved_since(double since, double md, double until) const;
  double slope_span_s() const;
  bool creeping(double t_end) const;  // the depth's fitted rate before t_end says it moves  // the depth left `md` in (since, until]

  DetectorOptions options_;
  Sink sink_;
  std::function<void(const std::string&)> note_;
  std::deque<DepthReport> depth_;   // in time order
  DepthNoiseFloor noise_;
  double reported_sd_ = 0;          // the largest sigma the depth reports carried
  std::optional<OpenStop> stop_;
  std::deque<Pending> pending_;     // in window-end order
  DetectorCounters counters_;
  std::optional<double> last_md_;
  double last_t_ = -1e300;
  double last_azimuth_ = 0;  // of the last station: for one whose azimuth was not measured
  bool in_stop_ = false;            // tally mode: inside a run of still windows
  std::size_t stops_ = 0;           // tally mode: stops seen
};

}  // namespace plumb::survey
