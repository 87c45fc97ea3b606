// A period in which one stream saw the drill string stand still, bounded by motion on both sides,
// in that stream's own clock. Its midpoint is what the two streams are matched on: a stream that
// notices motion late notices the stop early by about as much, so the midpoint keeps no lag.
#pragma once

namespace plumb::clock_sync {

struct StillRun {
  double begin_s = 0;  // between the last moving and the first still observation
  double end_s = 0;    // between the last still and the first moving observation
  double mid_s() const { return 0.5 * (begin_s + end_s); }
  double duration_s() const { return end_s - begin_s; }
};

}  // namespace plumb::clock_sync
