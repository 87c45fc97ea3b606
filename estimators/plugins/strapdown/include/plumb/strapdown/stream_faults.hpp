// What the sample stream itself got wrong, and what it costs: samples lost (a step well above the
// nominal interval) bridged by the mechanization over the gap, with the process noise of what the
// lost readings could have been; samples sent twice (the same stamp, or the same record again
// under a later stamp) dropped. Both counted, said once in a notice, and the rows after a gap say
// it was bridged.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/navigator_common.hpp"

namespace plumb::strapdown {

class StreamFaults {
 public:
  void reset();
  // Every navigable reading, dt after the one before: the spread of the readings about their own
  // local trend, from second differences over evenly spaced readings.
  void observe(const InputReading& in, double dt, double dt_nominal);
  // A gap of dt (the step that ends at t) where dt_nominal was due, as the input checks see it:
  // counted, and said once.
  void lost(double t, double dt, double dt_nominal, Counters& counters);
  // The same gap as the filter bridges it: the lost readings' share of the process noise of the
  // epoch that bridges it.
  void bridge(double dt, double dt_nominal);
  // A sample sent twice at t (dropped by the input checks).
  void repeat(double t, bool same_stamp);
  // The epoch's process noise (dt long) with what the gaps since the last epoch cost; forgets them.
  ProcessNoise widen(const ProcessNoise& base, double dt);
  std::vector<std::string> take_notices();

 private:
  struct Recent {
    double t = 0;
    Eigen::Vector3d w, f;
  };
  Recent r0_, r1_;
  int recent_ = 0;
  double spread_w2_ = 0, spread_f2_ = 0;  // mean square per axis about the local trend
  double pending_att_ = 0, pending_vel_ = 0;  // variance per axis to add at the next epoch
  bool gap_said_ = false, repeat_said_ = false;
  std::vector<std::string> notices_;
};

}  // namespace plumb::strapdown
