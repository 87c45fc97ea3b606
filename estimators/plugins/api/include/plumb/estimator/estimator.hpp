// The estimator plugin API. An estimator consumes sensor samples in time order and emits attitude
// estimates; it may be windowed (static, integral, compensated: one estimate per window) or keep
// state for hours (a strapdown navigator emitting at its own rate). No DDS here: hosts feed it.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "plumb/core/estimate.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::estimator {

// A bad parameter name or value: the message names the parameter and says what is accepted.
struct ParameterError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct ParameterSpec {
  std::string name;
  std::string default_value;
  std::string description;
};

struct Info {
  std::string name;
  std::string description;
  std::string version;
  std::vector<ParameterSpec> parameters;
  bool uses_gyro = false;        // needs wx, wy, wz: the runner says so when the stream has none
};

using Parameters = std::map<std::string, std::string>;

// Samples an estimator refused, by reason (non-finite, saturated, time backwards, ...).
using Counters = std::map<std::string, std::uint64_t>;

// Contract of every call below (the plugins of estimators/ keep it; a new plugin must too):
//   blocks     none: no call waits for I/O, a lock or another thread; each runs to completion on
//              the caller's thread (push and flush cost what the samples' computation costs).
//   allocates  stated per call.
//   threads    one thread at a time per instance: an estimator is not thread-safe, and takes no
//              lock. Separate instances share no state and may run on separate threads at once.
//              The hosts (estimators/plugins/api Runner, components/plumb-estimator) call every instance
//              from one thread, the one that takes the samples from the transport.
class Estimator {
 public:
  // Destroyed through EstimatorPtr, by the plugin that made it (its own operator delete).
  virtual ~Estimator() = default;
  //   allocates: yes (the strings and the parameter list).
  virtual Info info() const = 0;
  // Applies parameters (names from info().parameters; missing ones take their defaults) and
  // resets all state. Throws ParameterError for an unknown name or a bad value.
  //   allocates: yes (the state is rebuilt). Call it before the first push.
  virtual void configure(const Parameters& params) = 0;
  // Feeds samples, oldest first; appends the estimates they complete to `out`. Never throws for
  // bad data: bad samples are rejected and counted, bad windows produce invalid estimates.
  //   allocates: yes, may on any call: for each estimate made (its strings, and `out` when it must
  //     grow; a caller that keeps one vector keeps its capacity); the windowed plugins when a
  //     window closes (the platform-angle fit's work arrays) or outgrows the longest so far; the
  //     strapdown navigator as its queues and smoother records grow.
  virtual void push(std::span<const Sample> samples, std::vector<Estimate>& out) = 0;
  // End of the stream: appends an estimate for the samples not yet covered, if there are any.
  //   allocates: as push. The estimator then waits for configure (a new stream).
  virtual void flush(std::vector<Estimate>& out) = 0;
  //   allocates: yes (the map).
  virtual Counters counters() const = 0;
  // What the estimator has to say once, as it arises (a stream it cannot estimate and why, the
  // noise it read off the data): hosts log it and put the latest on plumb/status. Returns and
  // forgets the messages since the last call.
  virtual std::vector<std::string> take_notices() { return {}; }
};

// An estimator that a plugin created: destroyed by the plugin's own destroy function.
using EstimatorPtr = std::unique_ptr<Estimator, std::function<void(Estimator*)>>;

}  // namespace plumb::estimator

// --- plugin ABI -----------------------------------------------------------------------------
// A plugin is libplumb_estimator_<name>.so (the file name is its one name; info().name must
// equal it) exporting
//   extern "C" const plumb_estimator_plugin* plumb_estimator_plugin();
// PLUMB_ESTIMATOR_ABI is a hash of this header and the types it passes (core/sample.hpp,
// core/estimate.hpp): a plugin built against other versions of them is refused at load time.
#include "plumb/estimator/abi.hpp"

extern "C" {
struct plumb_estimator_plugin {
  const char* abi;  // first member, read by the plugin facility (plumb/plugin/library.hpp)
  const char* description;
  plumb::estimator::Estimator* (*create)();
  void (*destroy)(plumb::estimator::Estimator*);
};
}

// Defines the entry point of a plugin whose estimator class is default-constructible.
#define PLUMB_ESTIMATOR_PLUGIN(CLASS, DESCRIPTION)                                                    \
  extern "C" __attribute__((visibility("default"))) const struct plumb_estimator_plugin* plumb_estimator_plugin() { \
    static const struct ::plumb_estimator_plugin plugin{                                                     \
        PLUMB_ESTIMATOR_ABI, DESCRIPTION, []() -> plumb::estimator::Estimator* { return new CLASS(); }, \
        [](plumb::estimator::Estimator* e) { delete e; }};                                            \
    return &plugin;                                                                                   \
  }
