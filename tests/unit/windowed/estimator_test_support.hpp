// Helpers shared by the plugin tests: simulate a scenario and run it through a plugin by name.
#pragma once

#include <string>
#include <vector>

#include "plumb/estimator/loader.hpp"
#include "plumb/sim/platform.hpp"

namespace plumb::test {

inline std::vector<Sample> simulate(const sim::Scenario& s) {
  sim::PlatformSimulator simulator(s);
  return simulator.run();
}

inline std::vector<Estimate> run_plugin(const std::string& name, const std::vector<Sample>& samples,
                                        estimator::Parameters params = {{"window", "0"}}) {
  auto e = estimator::load_estimator(name);
  e->configure(params);
  std::vector<Estimate> out;
  e->push(samples, out);
  e->flush(out);
  return out;
}

inline const char* const kRotatingPlugins[] = {"integral", "compensated"};
inline const char* const kAllPlugins[] = {"static", "integral", "compensated"};

}  // namespace plumb::test
