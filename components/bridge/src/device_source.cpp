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
      open_failure_reported_ = false;
      on_event_(r.event, options_.path);
      break;
    case SerialPort::Event::Closed:
      open_failure_reported_ = false;
      on_event_(r.event, port_.last_error());
      break;
    case SerialPort::Event::OpenFailed:
      if (!open_failure_reported_) on_event_(r.event, port_.last_error());
      open_failure_reported_ = true;
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
