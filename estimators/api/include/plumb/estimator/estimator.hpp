// The estimator plugin API. An estimator consumes sensor samples in time order and emits attitude
// estimates; it may be windowed (static, integral, compensated: one estimate per window) or keep
// state for hours (a strapdown navigator emitting at its own rate). No DDS here: hosts feed it.
#pragma once

#include <cstdint>
#include <map>
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
  bool uses_gyro = false;        // needs wx, wy, wz
  bool stateful = false;         // carries state across windows (navigation)
};

using Parameters = std::map<std::string, std::string>;

// Samples an estimator refused, by reason (non-finite, saturated, time backwards, ...).
using Counters = std::map<std::string, std::uint64_t>;

class Estimator {
 public:
  virtual ~Estimator() = default;
  virtual Info info() const = 0;
  // Applies parameters (names from info().parameters; missing ones take their defaults) and
  // resets all state. Throws ParameterError for an unknown name or a bad value.
  virtual void configure(const Parameters& params) = 0;
  // Feeds samples, oldest first; appends the estimates they complete to `out`. Never throws for
  // bad data: bad samples are rejected and counted, bad windows produce invalid estimates.
  virtual void push(std::span<const Sample> samples, std::vector<Estimate>& out) = 0;
  // End of the stream: appends an estimate for the samples not yet covered, if there are any.
  virtual void flush(std::vector<Estimate>& out) = 0;
  virtual Counters counters() const = 0;
};

}  // namespace plumb::estimator

// --- plugin ABI -----------------------------------------------------------------------------
// A plugin is libplumb_estimator_<name>.so exporting
//   extern "C" const plumb_estimator_plugin_v1* plumb_estimator_plugin();
// The host refuses a plugin whose abi_version differs from PLUMB_ESTIMATOR_ABI_VERSION.
#define PLUMB_ESTIMATOR_ABI_VERSION 1u

extern "C" {
struct plumb_estimator_plugin_v1 {
  unsigned abi_version;
  const char* name;
  const char* description;
  plumb::estimator::Estimator* (*create)();
  void (*destroy)(plumb::estimator::Estimator*);
};
}

// Defines the entry point of a plugin whose estimator class is default-constructible.
#define PLUMB_ESTIMATOR_PLUGIN(CLASS, NAME, DESCRIPTION)                                              \
  extern "C" __attribute__((visibility("default"))) const plumb_estimator_plugin_v1* plumb_estimator_plugin() { \
    static const plumb_estimator_plugin_v1 plugin{                                                    \
        PLUMB_ESTIMATOR_ABI_VERSION, NAME, DESCRIPTION,                                               \
        []() -> plumb::estimator::Estimator* { return new CLASS(); },                                 \
        [](plumb::estimator::Estimator* e) { delete e; }};                                            \
    return &plugin;                                                                                   \
  }
