// A serial device in binary or ASCII mode (or detected): bytes -> StreamParser -> samples.
// The device going away flushes the parser (a partial frame counts as truncated) and is
// reopened with back-off by SerialPort.
#pragma once

#include <functional>

#include "plumb/bridge/serial_port.hpp"
#include "plumb/bridge/source.hpp"
#include "plumb/bridge/stream_parser.hpp"

namespace plumb::bridge {

class DeviceSource final : public SampleSource {
 public:
  // `on_event` (optional) hears of the device opening and closing, and of the first failed
  // open after each of those (not of every retry), for the log.
  DeviceSource(const SerialOptions& options, Mode mode, Counters& counters,
               std::function<void(SerialPort::Event, const std::string&)> on_event = {});
  bool poll(std::vector<Sample>& out, std::chrono::milliseconds max_wait) override;
  std::string describe() const override;
  bool healthy() const override { return port_.is_open(); }
  std::string last_error() const override;

 private:
  SerialOptions options_;
  SerialPort port_;
  StreamParser parser_;
  std::function<void(SerialPort::Event, const std::string&)> on_event_;
  std::vector<std::uint8_t> buffer_;
  std::uint64_t open_failures_ = 0;  // consecutive failed opens since the device was last open
};

}  // namespace plumb::bridge
