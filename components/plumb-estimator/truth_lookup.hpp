// `plumb-estimator --truth`: follows plumb/sim/truth (published by plumb-sim, one message per
// batch) so that each estimate can be printed with its error against what really happened.
#pragma once

#include <deque>
#include <optional>

#include "plumb/topics/all.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::estimator_component {

class TruthLookup {
 public:
  TruthLookup(transport::Participant& participant, const std::string& topic);
  // Takes what arrived; call before at().
  void update();
  // The truth nearest to `t_s` (simulation time, s), if one within 1 s of it arrived.
  std::optional<topics::Truth> at(double t_s) const;

 private:
  transport::Reader<topics::Truth> reader_;
  std::deque<topics::Truth> recent_;  // newest last; a few minutes at plumb-sim's batch rate
};

}  // namespace plumb::estimator_component
