// The stillness decision taken with a fixed lag: the detector judges each reading as it comes, the
// reading and its decision wait here, and the filter takes the reading once it is lag_s old, with
// the decision corrected by what the detector saw since. A drilling string that speeds up over
// seconds is seen moving only after it moved: a reading in a stop that ended less than lag_s after
// it was not still. A stop that ends thus takes back its last lag_s of stillness (its end moves
// back to the first reading no longer still), and a stop shorter than lag_s vanishes (neither its
// start nor its end reaches the filter). No filter step is undone: the filter simply runs lag_s
// behind the detector. lag_s = 0: every reading passes at once, as judged.
#pragma once

#include <cstddef>
#include <optional>

#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/ring_queue.hpp"
#include "plumb/strapdown/stillness.hpp"

namespace plumb::strapdown {

class StillnessLag {
 public:
  struct Entry {
    InputReading reading;
    StillnessState still;
  };
  void reset(double lag_s);
  // The next reading (times increasing) as the detector judged it.
  void push(const InputReading& reading, const StillnessState& decision);
  // The oldest reading once it is lag_s older than the newest, with its decision as known now.
  std::optional<Entry> pop_ready();
  // End of data: the oldest reading whatever its age (its decision cannot change any more).
  std::optional<Entry> pop_any();
  bool empty() const { return queue_.empty(); }
  double lag_s() const { return lag_s_; }

 private:
  bool take_back(double end_t, bool ended);

  RingQueue<Entry> queue_;  // (a ring: no allocation per reading once it holds lag_s of them)
  double lag_s_ = 0;
  bool newest_still_ = false;  // the detector's decision at the newest reading pushed
};

}  // namespace plumb::strapdown
