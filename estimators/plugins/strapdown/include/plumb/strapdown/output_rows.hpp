// The navigator's output rows: the readings since the last row (totals, dip, rpm, the magnetic
// toolface), the attitude and navigation state with their sigmas, the row's reason or warnings,
// the output rate, and in smoothing mode the rows held back for the backward smoother, whose
// epochs it stores.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/core/estimate.hpp"
#include "plumb/strapdown/alignment.hpp"
#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/filter_state.hpp"
#include "plumb/strapdown/mechanization.hpp"
#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/navigator_config.hpp"
#include "plumb/strapdown/smoother.hpp"

namespace plumb::strapdown {

// What a row says beyond its own readings, as the navigator's parts have it at the row's instant.
struct RowContext {
  bool aligned = false;
  std::string why;                      // why the row cannot navigate; empty when it does
  const FilterState* filter = nullptr;  // the state and covariance, when aligned
  bool still = false;
  std::uint32_t stops = 0;              // still periods with zero-velocity updates so far
  std::string azimuth_reference;
  std::string field_warning;            // why the last stop gave no azimuth update
  std::string motion_warning;           // the along-hole motion is not measured (unseen_motion.hpp)
  std::string range_warning;            // readings of this row clipped at a sensor's range (sensor_range.hpp)
  // The reference field's direction in the navigation frame, when the magnetometer serves azimuth:
  // the magnetic toolface comes from it (else the gyro toolface, from north).
  std::optional<Eigen::Vector3d> field_direction_n;
  // How far the instants the readings are integrated at stray from the true ones as measured from
  // the stamps (stamp_clock.hpp), s: with time_tag_sd_s, what a turning tool's toolface is unsure by.
  double measured_instant_sd_s = 0;
};

class OutputRows {
 public:
  void reset(const NavigatorConfig& config);
  // Every reading that reaches navigation (aligned or not) counts into the next row.
  void add_reading(const InputReading& in);
  // A gap ending at t: the rows from t to a period after it say that prediction alone bridged it
  // (rows before it may come later: the filter runs behind the readings, stillness_lag.hpp).
  void note_gap(double t) {
    gap_warning_from_ = t;
    gap_warning_until_ = t + 1.0 / config_.output_rate_hz;
  }
  // Whether a row is due at t: the first call starts the rows, a period later.
  bool due(double t);
  // Whether a row will be due at t (without starting the rows).
  bool output_due(double t) const { return t >= next_output_t_ - 1e-9; }
  // The next row at t, or at t at the latest.
  void due_at(double t) { next_output_t_ = t; }
  void due_by(double t) { next_output_t_ = std::min(next_output_t_, t); }
  // The rows start now: the next due() at t gives a row (a run with nothing navigable).
  void start_at(double t) {
    output_started_ = true;
    next_output_t_ = t;
  }
  // Readings since the last row, up to last_t.
  bool readings_since_row(double last_t) const { return row_stats_.count() > 0 && last_t > last_row_t_; }
  // The row at t (due(t) said so): to out, or held for the smoother.
  void emit(double t, const RowContext& context, Counters& counters, std::vector<Estimate>& out);

  // Smoothing: the filter's epochs (the alignment's, then each with the transition from the one before).
  void store_epoch(const FilterState& filter, const FilterState::Prediction& prediction);
  void store_alignment(const FilterState& filter);
  std::size_t smoother_epochs() const { return smoother_.size(); }
  // End of stream, smoothing: every held row, smoothed where it has an epoch.
  void flush_smoothed(const RowContext& context, std::vector<Estimate>& out);

 private:
  // note_at: where the reason's near-vertical toolface note begins (npos: none).
  Estimate row(double t, const RowContext& context, std::size_t& note_at) const;
  // Returns what a row near vertical says of its toolface (empty above toolface_switch).
  std::string fill_attitude(Estimate& e, const NavState& x, const StateMatrix& p, const RowContext& context) const;
  std::string toolface_from_north(Estimate& e, const Eigen::Matrix3d& c_bn, const Eigen::Matrix3d& p_att,
                                  double inclination, const RowContext& context) const;

  NavigatorConfig config_;
  double next_output_t_ = 0;
  bool output_started_ = false;
  double last_row_t_ = 0;
  double gap_warning_from_ = -1, gap_warning_until_ = -1;
  StillStats row_stats_;  // readings since the last row (totals, dip, rpm)
  Eigen::Vector3d last_b_ = Eigen::Vector3d::Zero();
  bool last_b_valid_ = false;
  RtsSmoother smoother_;
  struct PendingRow {
    Estimate row;
    std::optional<std::size_t> epoch;  // smoother epoch of the row (none before alignment)
    std::size_t toolface_note_at = std::string::npos;  // where the reason's near-vertical note begins
  };

  std::vector<PendingRow> pending_;
};

}  // namespace plumb::strapdown
