// The strapdown navigator: the owner that wires its parts, each in its own header: the input
// checks, the stillness watch and its lag, the alignment, the filter state, the stop updates, and the output
// rows with the optional backward smoother. Plain C++ (no plugin API): the plugin
// (strapdown_estimator.cpp) and the tests drive it through push/flush.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "plumb/core/estimate.hpp"
#include "plumb/core/sample.hpp"
#include "plumb/strapdown/aligner.hpp"
#include "plumb/strapdown/clipped_spin.hpp"
#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/filter_state.hpp"
#include "plumb/strapdown/input_checks.hpp"
#include "plumb/strapdown/mechanization.hpp"
#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/navigator_config.hpp"
#include "plumb/strapdown/output_rows.hpp"
#include "plumb/strapdown/stillness.hpp"
#include "plumb/strapdown/stamp_clock.hpp"
#include "plumb/strapdown/stillness_lag.hpp"
#include "plumb/strapdown/stillness_watch.hpp"
#include "plumb/strapdown/sensor_range.hpp"
#include "plumb/strapdown/shock_rebound.hpp"
#include "plumb/strapdown/stop_updates.hpp"
#include "plumb/strapdown/stream_faults.hpp"
#include "plumb/strapdown/temperature_drift.hpp"
#include "plumb/strapdown/unseen_motion.hpp"

namespace plumb::strapdown {

class Navigator {
 public:
  explicit Navigator(const NavigatorConfig& config = {});
  // The input checks bump counters through pointers into counters_: a copy would bump the
  // original's; a move keeps the nodes.
  Navigator(const Navigator&) = delete;
  Navigator& operator=(const Navigator&) = delete;
  Navigator(Navigator&&) = default;
  Navigator& operator=(Navigator&&) = default;
  void configure(const NavigatorConfig& config);
  // Samples oldest first; appends the rows they complete (none in smoothing mode).
  void push(const Sample& s, std::vector<Estimate>& out);
  // End of stream: the rows still pending (all of them, smoothed, in smoothing mode).
  void flush(std::vector<Estimate>& out);
  const std::map<std::string, std::uint64_t>& counters() const { return counters_; }
  // What the navigator has to say once (a run that cannot align and why, the noise it measured):
  // returns and forgets the messages since the last call.
  std::vector<std::string> take_notices();

  // Introspection for tests.
  bool aligned() const { return aligned_; }
  const NavState& state() const { return filter_.state(); }
  const Eigen::Vector3d& gyro_bias() const { return filter_.gyro_bias(); }
  const Eigen::Vector3d& accel_bias() const { return filter_.accel_bias(); }
  double gyro_scale() const { return filter_.gyro_spin().z(); }
  Eigen::Vector2d gyro_leak() const { return filter_.gyro_spin().head<2>(); }
  Eigen::Vector2d gyro_g() const { return filter_.gyro_g(); }
  double mag_axial_bias() const { return filter_.mag_axial_bias(); }
  const StateMatrix& covariance() const { return filter_.covariance(); }
  bool still() const { return watch_.still(); }
  double time() const { return checks_.last_t().value_or(0.0); }
  std::size_t smoother_epochs() const { return rows_.smoother_epochs(); }

 private:
  using Input = InputReading;
  void reset();
  void count(const char* name, std::uint64_t n = 1) { counters_[name] += n; }
  void process(const Input& in, std::vector<Estimate>& out);
  void navigate(Input in, const StillnessState& still, std::vector<Estimate>& out);
  void bridge_gap(const Input& from, const Input& at, const Input& in, double dt_nominal);
  void before_alignment(const Input& in, std::vector<Estimate>& out);
  void align(const Input& in);
  void epoch(const Input& in, std::vector<Estimate>& out);
  void emit(double t, std::vector<Estimate>& out);
  RowContext row_context() const;
  std::string reason() const;

  NavigatorConfig config_;
  Counters counters_;
  // Navigation.
  bool aligned_ = false;
  std::optional<Input> prev_, prev2_;
  // The instants the mechanization integrates prev_ and prev2_ at (their stamps, but where these jitter).
  StampClock clock_;
  double prev2_instant_ = 0;
  double last_epoch_t_ = 0;
  StillnessState still_state_;
  // The parts.
  InputChecks checks_;
  StillnessWatch watch_;
  Aligner aligner_;
  FilterState filter_;
  StopUpdates stops_;
  OutputRows rows_;
  StillnessLag lag_;
  UnseenMotion unseen_;
  StreamFaults faults_;
  SensorRange ranges_;
  ClippedSpin spin_;
  ShockRebound shocks_;
  TemperatureDrift temperature_;
};

}  // namespace plumb::strapdown
