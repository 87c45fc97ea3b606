// What the sample stream itself got wrong, and what it costs: samples lost (a step well above the
// nominal interval) bridged by the mechanization over the gap, with the process noise of what the
// lost readings could have been; samples sent twice (the same stamp, or the same record again
// under a later stamp) dropped. Both counted, said once in a notice, and the rows after a gap say
// it was bridged.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/unseen_motion.hpp"

namespace plumb::strapdown {

class StreamFaults {
 public:
  void reset();
  // Every navigable reading, dt after the one before: the spread of the readings about their own
  // local trend, from second differences over evenly spaced readings, and the rate across the axis
  // over the last second.
  void observe(const InputReading& in, double dt, double dt_nominal);
  // The tool-frame rate across the axis (x, y) over the last second: what a drill string turns
  // across its axis is its hole's curvature and the gyros' biases, steady over seconds; one reading
  // holds its noise too, and held through a gap of T that noise is an angle of noise T.
  Eigen::Vector2d cross_rate() const { return cross_rate_; }
  // A gap of dt (the step that ends at t) where dt_nominal was due, as the input checks see it:
  // counted, and said once.
  void lost(double t, double dt, double dt_nominal, Counters& counters);
  // The same gap as the filter bridges it, from the reading before (prev) to this one (in), the tool
  // frame to NED c_bn: the lost readings' share of the process noise of the epoch that bridges it.
  void bridge(const InputReading& prev, const InputReading& in, double dt_nominal, const Eigen::Matrix3d& c_bn);
  // The last gap's turn about the tool's axis as the field across the axis shows it
  // (unseen_turn_across_gap; the field's part across the axis after the gap `field_across` and its
  // whole `field`, microtesla): the part of it to take, weighed against what the gap may hide about
  // the axis and the magnetometers' noise; what the gap may hide about the axis shrinks to match.
  double axial_turn_seen(double turn, double field_across, double field);
  // The turn the gaps since the last epoch may hide, for the epoch; forgets it.
  void add_to(UnseenMotionNoise& noise);
  // A sample sent twice at t (dropped by the input checks).
  void repeat(double t, bool same_stamp);
  // The epoch's process noise (dt long) with what the gaps since the last epoch cost; forgets them.
  ProcessNoise widen(const ProcessNoise& base, double dt);
  std::vector<std::string> take_notices();
  // The readings a drilling tool's mechanization steps through across a gap, from `prev` (the
  // reading before it, its attitude c_bn) to `in`: one per nominal interval, the rate about the
  // axis on its line between the two and across it `cross_rate` (cross_rate()), the specific force f_n held in the navigation frame (gravity's reaction: a
  // string's acceleration over seconds is millimetres per second squared) seen from the attitude
  // the rates turn the tool to, with the accelerometers' estimated bias. Not one step: through a
  // turn of hundreds of degrees (a second at 30 rpm) a step integrates the force as if the turn were
  // small. Not the readings either side: one reading holds the bit's vibration (1-2 m/s^2), and a
  // line to it over seconds is a velocity error of metres per second; nor their mean: 2 m/s^2 of
  // vibration leaves 0.07 m/s^2 in a 6 s mean, 0.13 m over a 2 s gap. The first is prev's instant,
  // the last in's.
  static std::vector<InputReading> gap_readings(const InputReading& prev, const InputReading& in,
                                                const Eigen::Matrix3d& c_bn, double dt_nominal,
                                                const Eigen::Vector3d& f_n, const Eigen::Vector3d& accel_bias,
                                                const Eigen::Vector2d& cross_rate);

 private:
  struct Recent {
    double t = 0;
    Eigen::Vector3d w, f;
    std::optional<Eigen::Vector3d> b;
  };
  Recent r0_, r1_;
  int recent_ = 0;
  double spread_w2_ = 0, spread_f2_ = 0, spread_b2_ = 0;
  Eigen::Vector2d cross_rate_ = Eigen::Vector2d::Zero();
  double cross_rate_var_ = 0;  // of cross_rate_'s noise, per axis (rad/s)^2
  bool cross_rate_started_ = false;
  double spin_mean_ = 0, spin_var_ = 0;  // the rate about the axis over the last seconds (rad/s, its square)
  double pending_att_ = 0, pending_vel_ = 0;  // variance per axis to add at the next epoch
  double pending_axial_ = 0;  // about the axis, rad
  Eigen::Vector3d pending_axis_ = Eigen::Vector3d::Zero();  // the tool's axis (navigation frame) at the last gap
  Eigen::Matrix3d pending_force_ = Eigen::Matrix3d::Zero();
  bool gap_said_ = false, repeat_said_ = false;
  std::vector<std::string> notices_;
};

}  // namespace plumb::strapdown
