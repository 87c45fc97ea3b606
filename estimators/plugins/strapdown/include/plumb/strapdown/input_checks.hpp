// The navigator's input checks: each sample refused (counted by why) or taken as a reading, a
// saturated sensor's last good value held, no field where the magnetometer reads none, the
// nominal sample interval and the gaps; and, for gyros stamped late or early, the readings held
// until the gyro series reaches their instant.
#pragma once

#include <deque>
#include <optional>
#include <utility>

#include <Eigen/Core>

#include "plumb/core/sample.hpp"
#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/navigator_config.hpp"

namespace plumb::strapdown {

class InputChecks {
 public:
  // The per-sample counters are bumped through pointers into counters (map nodes stay put).
  void reset(const NavigatorConfig& config, Counters& counters);
  struct Verdict {
    bool navigable = false;
    bool first_without_field = false;  // the stream's first reading, and it has no field
    bool gap = false;                  // more than max_gap_s after the reading before
    bool repeated = false;             // a sample sent twice (dropped): the same stamp, or the same record
    bool same_stamp = false;
    double lost_dt = 0;                // > 0: samples lost in this step (kDropoutFactor nominal intervals)
  };
  Verdict accept(const Sample& s, InputReading& in, Counters& counters);
  // gyro_time_offset_s: the gyro reading stamped t was measured at t + offset. A reading waits in
  // a queue until the gyro series reaches its instant; next_ready gives the readings in turn, with
  // the rate interpolated at it.
  void queue(const InputReading& in);
  std::optional<InputReading> next_ready();
  // End of stream: the readings still waiting, with the last gyro reading there is.
  std::optional<InputReading> next_waiting();

  std::optional<double> last_t() const { return last_t_; }
  double dt_nominal() const { return dt_nominal_; }
  // The steps' spread about the nominal (about their rms where the stamps jitter).
  double dt_jitter() const { return dt_jitter_; }
  // A step this long lost samples: beyond kDropoutFactor nominal intervals and beyond what the
  // stamps' own jitter makes of one interval.
  bool lost_samples(double dt) const {
    return dt_nominal_ > 0 && dt > kDropoutFactor * dt_nominal_ && dt - dt_nominal_ > kJitterSigmas * dt_jitter_;
  }
  // The stream's seq counts its samples: readings are in their seq's order even where their stamps
  // are not.
  bool ordered_by_seq() const { return seq_counts_; }
  // Only samples without gyros so far: rows say strapdown needs them.
  bool no_gyro_at_all() const { return saw_no_gyro_ && !saw_gyro_; }

 private:
  Eigen::Vector3d rate_at(double stamp) const;
  bool behind_within_jitter(const Sample& s) const;

  NavigatorConfig config_;
  std::uint64_t* samples_counter_ = nullptr;
  std::uint64_t* accepted_counter_ = nullptr;
  std::optional<double> last_t_;
  std::optional<Eigen::Vector3d> last_good_w_, last_good_f_;
  // The last navigable sample's record, to know it when it comes again under a later stamp.
  std::uint64_t last_seq_ = 0;
  bool seq_counts_ = false;
  Eigen::Vector3d last_f_ = Eigen::Vector3d::Zero(), last_w_ = Eigen::Vector3d::Zero();
  std::deque<InputReading> shift_queue_;
  std::deque<std::pair<double, Eigen::Vector3d>> gyro_history_;
  double dt_nominal_ = 0;
  double dt_jitter_ = 0;  // the intervals' spread about the nominal (mean absolute deviation x 1.25)
  bool saw_gyro_ = false, saw_no_gyro_ = false;
};

}  // namespace plumb::strapdown
