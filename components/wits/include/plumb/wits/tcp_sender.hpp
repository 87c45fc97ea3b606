// The rig's side of a WITS TCP feed: a client that connects to a WITS reader (plumb-wits --listen)
// and writes frames to it. Written once for everything that plays a rig (plumb-wits-send
// --connect, plumb-sim --wits). The reader may start after the rig: the connect retries while the
// port refuses, up to a deadline, and says why it gave up.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace plumb::wits {

class TcpSender {
 public:
  // HOST (a name or an IPv4 address) and PORT; nothing is connected yet.
  TcpSender(std::string host, int port);
  ~TcpSender();
  TcpSender(const TcpSender&) = delete;
  TcpSender& operator=(const TcpSender&) = delete;

  // Tries to connect until `wait` has passed (at least once; every `retry` while nobody listens),
  // or `stop` says so. A single attempt's handshake is bounded too (by what is left of `wait`, at
  // least 0.2 s and at most 2 s), so a host that never answers costs no more than that. False when
  // it gave up: last_error() then names HOST:PORT and the system's reason.
  bool connect(std::chrono::milliseconds wait, const std::function<bool()>& stop = {},
               std::chrono::milliseconds retry = std::chrono::milliseconds(100));
  bool is_open() const { return fd_ >= 0; }

  // Writes every byte (connected only). False when the peer went away: the socket is then closed
  // and last_error() says why; the next connect() opens a new one.
  bool send(const std::string& bytes);
  // Closes the connection once the peer has taken everything sent (at most 2 s), so that no whole
  // frame is lost to the close.
  void close_when_sent();

  // "HOST:PORT".
  std::string address() const;
  // Why the last connect or send failed ("cannot connect to 127.0.0.1:5000: Connection refused").
  const std::string& last_error() const { return last_error_; }

 private:
  bool attempt(std::chrono::milliseconds handshake);
  void close_socket();

  std::string host_;
  int port_;
  int fd_ = -1;
  std::string last_error_;
};

// Writes every byte of `bytes` to the connected socket `fd` (no SIGPIPE); false when it failed.
bool send_all(int fd, const std::string& bytes);
// Closes `fd` once the peer has read everything sent (nothing left in the send queue), at most 2 s.
void close_when_sent(int fd);

}  // namespace plumb::wits
