// Where the rig's WITS bytes come from: a TCP connection this computer opens (the rig's WITS
// server), one it accepts (the rig sends to us), or a serial port. Each link keeps itself up:
// a lost connection or device is opened again with back-off, for ever, and counted.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace plumb::wits {

struct LinkCounters {
  std::uint64_t connects = 0;     // connections made or accepted, device opens
  std::uint64_t reconnects = 0;   // of those, after the first
  std::uint64_t disconnects = 0;  // connections or devices lost (closed by the peer, errors)
  std::uint64_t bytes_read = 0;
};

class Link {
 public:
  enum class Event { None, Data, Opened, Closed, OpenFailed };
  struct ReadResult {
    std::size_t bytes = 0;
    Event event = Event::None;  // Closed: the byte stream ended (a frame in progress is cut)
  };
  virtual ~Link() = default;
  // Opens when due, then waits up to `timeout` for bytes and reads what is there.
  virtual ReadResult read(std::uint8_t* buffer, std::size_t capacity, std::chrono::milliseconds timeout) = 0;
  virtual bool is_open() const = 0;
  // "TCP client to 10.0.0.5:5000", for the log.
  virtual std::string describe() const = 0;
  // The peer of the open connection, or what failed last.
  virtual std::string last_event() const = 0;
  virtual const LinkCounters& counters() const = 0;
};

struct Backoff {
  std::chrono::milliseconds min{100};
  std::chrono::milliseconds max{5000};
};

// HOST:PORT (a name or an IPv4 address); throws std::invalid_argument naming `what` otherwise.
void split_host_port(const std::string& text, const std::string& what, std::string& host, int& port);
// A TCP port, 1-65535; throws std::invalid_argument naming `what` otherwise.
int parse_port(const std::string& text, const std::string& what);
// A server's [ADDRESS:]PORT (ADDRESS an IPv4 address; none: every interface, 0.0.0.0); throws
// std::invalid_argument naming `what` otherwise.
void split_listen_address(const std::string& text, const std::string& what, std::string& address, int& port);

std::unique_ptr<Link> make_tcp_client(const std::string& host, int port, Backoff backoff = {});
// Listens on ADDRESS:PORT (empty address: every interface). One connection at a time: a new one
// replaces the current one (a rig that reconnects after a break we never saw). Throws
// std::runtime_error when the port cannot be bound.
std::unique_ptr<Link> make_tcp_server(const std::string& address, int port);
// Throws std::invalid_argument for a baud rate that is not standard. Does not open yet.
std::unique_ptr<Link> make_serial_link(const std::string& path, int baud, Backoff backoff = {});

}  // namespace plumb::wits
