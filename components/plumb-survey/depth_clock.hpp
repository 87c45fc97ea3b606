// plumb-survey's depth clock: the rig stamps its depth on its own clock (plumb-wits: this computer's
// clock when the frame came), the tool its samples on the tool's. Depth reports are held until the
// offset and drift between the two are known, then handed to the station detector on the sensors'
// clock. Known from --depth-clock-offset / --depth-clock-drift-ppm, or estimated from the stops
// both streams see (plumb/clock_sync). No DDS here: the caller feeds reports and samples.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "plumb/clock_sync/clock_fit.hpp"
#include "plumb/clock_sync/depth_stillness.hpp"
#include "plumb/clock_sync/sensor_stillness.hpp"
#include "plumb/core/sample.hpp"
#include "plumb/survey/station_detector.hpp"

namespace plumb::survey_component {

struct DepthClockOptions {
  std::optional<double> offset_s;    // given: depth clock - sensor clock; no estimation
  std::optional<double> drift_ppm;   // given with or without the offset (offset 0 then)
  double still_tolerance_m = 0.02;   // the depth's spread when standing
  std::size_t max_held = 200000;     // depth reports held while unaligned (the oldest dropped, counted)
};

// Throws std::invalid_argument naming the option when a given offset or drift is not usable.
void check_depth_clock_options(const DepthClockOptions& options);

class DepthClock {
 public:
  explicit DepthClock(DepthClockOptions options);
  bool given() const { return given_.has_value(); }
  void add_depth(const survey::DepthReport& on_depth_clock);
  void add_sensor(const Sample& s);
  // Depth reports now on the sensors' clock, in time order; empty while the clocks are not aligned.
  std::vector<survey::DepthReport> take_aligned();
  // The alignment in force (given or estimated), if any.
  const std::optional<clock_sync::ClockEstimate>& alignment();
  // One line: the alignment, or what it waits for.
  std::string describe();
  // Counters for plumb/status (names beginning depth_clock_).
  std::vector<std::pair<std::string, std::uint64_t>> counters();
  std::uint64_t held() const { return held_.size(); }

 private:
  DepthClockOptions options_;
  std::optional<clock_sync::ClockEstimate> given_;
  clock_sync::DepthStillness depth_still_;
  clock_sync::SensorStillness sensor_still_;
  clock_sync::ClockFit fit_;
  std::deque<survey::DepthReport> held_;
  std::uint64_t dropped_ = 0, out_of_order_ = 0;
  double last_sensor_t_ = -1e300, last_depth_t_ = -1e300;
};

}  // namespace plumb::survey_component
