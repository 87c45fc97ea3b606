// Every simulator (platform, drilling run, walk) produces samples one at a time with next(); this
// is their common "all that is left at once" for tests and file output.
#pragma once

#include <vector>

#include "plumb/core/sample.hpp"

namespace plumb::sim {

template <class Simulator>
std::vector<Sample> run_all(Simulator& simulator, std::vector<TruthSample>* truth) {
  std::vector<Sample> out;
  const std::size_t remaining = simulator.done() ? 0 : simulator.sample_count() - simulator.index();
  out.reserve(remaining);
  if (truth) truth->reserve(truth->size() + remaining);
  while (!simulator.done()) {
    TruthSample ts;
    out.push_back(simulator.next(&ts));
    if (truth) truth->push_back(ts);
  }
  return out;
}

}  // namespace plumb::sim
