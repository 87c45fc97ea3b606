// Where the bridge's samples come from: a serial device (device_source.hpp) or a sensor CSV
// replayed at a chosen rate (replay_source.hpp). Samples come out decoded but not yet checked.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "plumb/core/sample.hpp"

namespace plumb::bridge {

class SampleSource {
 public:
  virtual ~SampleSource() = default;
  // Appends the samples available now, waiting up to `max_wait` for some. False once the source
  // has ended for good (end of the replay file); a device never ends.
  virtual bool poll(std::vector<Sample>& out, std::chrono::milliseconds max_wait) = 0;
  // "serial /dev/ttyUSB0 at 921600 baud, binary frames" for the start-up line.
  virtual std::string describe() const = 0;
  // True while data can flow (device open, file being read).
  virtual bool healthy() const = 0;
  virtual std::string last_error() const = 0;
};

}  // namespace plumb::bridge
