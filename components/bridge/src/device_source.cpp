#include "plumb/bridge/device_source.hpp"

namespace plumb::bridge {

DeviceSource::DeviceSource(const SerialOptions& options, Mode mode, Counters& counters,
                           std::function<void(SerialPort::Event, const std::string&)> on_event)
    : options_(options), port_(options, counters), parser_(counters, mode, options.path), on_event_(std::move(on_event)),
      buffer_(16 * 1024) {}

bool DeviceSource::poll(std::vector<Sample>& out, std::chrono::milliseconds max_wait) {
  const auto r = port_.read(buffer_.data(), buffer_.size(), max_wait);
  if (r.bytes > 0) parser_.feed(std::span(buffer_.data(), r.bytes), out);
  if (r.event == SerialPort::Event::Closed) parser_.finish(out);
  if (!on_event_) return true;
  switch (r.event) {
    case SerialPort::Event::Opened:
      open_failures_ = 0;
      on_event_(r.event, options_.path);
      break;
    case SerialPort::Event::Closed:
      open_failures_ = 0;
      on_event_(r.event, port_.last_error());
      break;
    case SerialPort::Event::OpenFailed:
      // Reported at failures 1, 2, 4, 8...: a device missing for hours is said with its count at a
      // growing interval, never silently and never once per attempt.
      ++open_failures_;
      if ((open_failures_ & (open_failures_ - 1)) == 0)
        on_event_(r.event, port_.last_error() + " (attempt " + std::to_string(open_failures_) + ")");
      break;
    default:
      break;
  }
  return true;
}

std::string DeviceSource::describe() const {
  return "serial " + options_.path + " at " + std::to_string(options_.baud) + " baud, " +
         (parser_.mode() == Mode::Auto ? std::string("mode detected from the data")
                                       : std::string(mode_name(parser_.mode())) + " mode");
}

std::string DeviceSource::last_error() const {
  // The device's trouble matters more than one bad line.
  if (!port_.is_open() && !port_.last_error().empty()) return port_.last_error();
  return parser_.last_line_error().empty() ? port_.last_error() : parser_.last_line_error();
}

}  // namespace plumb::bridge
