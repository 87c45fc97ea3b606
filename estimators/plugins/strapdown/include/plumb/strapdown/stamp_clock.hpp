// The instant each reading is integrated at. A logger's stamps jitter (a millisecond is 14 % of a
// 100 Hz interval): a step taken from two stamps errs by both, and the attitude at a reading then
// errs by the rate times its stamp's error (a turning tool's toolface). Where the stamps jitter and
// a step is within that jitter, the reading is taken one nominal interval after the one before,
// pulled a little towards its own stamp so the instants follow the stamps over the run; any other
// step (samples lost, a gap, a stream whose stamps do not jitter, or jitter so much that they fall
// out of order in a stream whose seq does not place them) is the stamps' own.
#pragma once

namespace plumb::strapdown {

class StampClock {
 public:
  // A reading navigated without a step before it (the alignment's): its instant is its stamp.
  void restart(double t) { instant_ = t; }
  // The instant of the reading stamped t, whose step from the reading before is step_dt; the
  // stream's nominal interval and the spread of its steps about it (InputChecks), and whether the
  // step lost samples; in_seq_order: the stream's seq counts its readings (InputChecks), which then
  // come in that order even where a stamp is behind the one before.
  double next(double t, double step_dt, double dt_nominal, double step_spread, bool lost, bool in_seq_order);
  double instant() const { return instant_; }
  // How far the instants stray from the true ones, 1 sigma (s): a stamp's jitter as measured, or,
  // where the instants are drawn from the nominal interval, what the pull to the stamps leaves of it.
  double instant_sd(double dt_nominal, double step_spread, bool in_seq_order) const;

 private:
  double instant_ = 0;
};

}  // namespace plumb::strapdown
