// The serial link: the bridge's SerialPort (termios raw mode, reopened with back-off).
#include "plumb/bridge/serial_port.hpp"
#include "plumb/wits/link.hpp"

namespace plumb::wits {
namespace {

Link::Event event(bridge::SerialPort::Event e) {
  switch (e) {
    case bridge::SerialPort::Event::Data: return Link::Event::Data;
    case bridge::SerialPort::Event::Opened: return Link::Event::Opened;
    case bridge::SerialPort::Event::Closed: return Link::Event::Closed;
    case bridge::SerialPort::Event::OpenFailed: return Link::Event::OpenFailed;
    case bridge::SerialPort::Event::None: break;
  }
  return Link::Event::None;
}

class SerialLink final : public Link {
 public:
  SerialLink(const std::string& path, int baud, Backoff backoff)
      : port_({path, baud, backoff.min, backoff.max}, bridge_counters_), path_(path), baud_(baud) {}

  ReadResult read(std::uint8_t* buffer, std::size_t capacity, std::chrono::milliseconds timeout) override {
    const auto r = port_.read(buffer, capacity, timeout);
    c_.connects = bridge_counters_.opens;
    c_.reconnects = bridge_counters_.reopens;
    c_.disconnects = bridge_counters_.read_errors;
    c_.bytes_read = bridge_counters_.bytes_read;
    if (r.event == bridge::SerialPort::Event::Opened) last_ = "opened " + path_;
    if (r.event == bridge::SerialPort::Event::Closed || r.event == bridge::SerialPort::Event::OpenFailed)
      last_ = port_.last_error();
    return {r.bytes, event(r.event)};
  }
  bool is_open() const override { return port_.is_open(); }
  std::string describe() const override { return "serial port " + path_ + " at " + std::to_string(baud_) + " baud"; }
  std::string last_event() const override { return last_; }
  const LinkCounters& counters() const override { return c_; }

 private:
  bridge::Counters bridge_counters_;
  bridge::SerialPort port_;
  std::string path_;
  int baud_;
  LinkCounters c_;
  std::string last_;
};

}  // namespace

std::unique_ptr<Link> make_serial_link(const std::string& path, int baud, Backoff backoff) {
  return std::make_unique<SerialLink>(path, baud, backoff);
}

}  // namespace plumb::wits
