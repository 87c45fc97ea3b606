// Where plumb-wits-send writes its frames: a TCP connection it opens or accepts, or a
// pseudo-terminal standing in for the rig's serial line. `drop` ends the connection (the reader
// sees its stream end) and the next write opens a new one.
#pragma once

#include <memory>
#include <string>

namespace plumb::wits_send {

inline constexpr const char* kProgram = "plumb-wits-send";

class Output {
 public:
  virtual ~Output() = default;
  // Writes every byte, opening (and waiting for) the connection first when there is none. False
  // when stopped (SIGINT/SIGTERM) or the peer went away mid-write (the caller goes on: the frame is
  // then a cut one for the reader).
  virtual bool write(const std::string& bytes) = 0;
  // Ends the current connection after everything written has been taken by the reader.
  virtual void drop() = 0;
  virtual std::string describe() const = 0;
};

std::unique_ptr<Output> make_tcp_client_output(const std::string& host, int port);
std::unique_ptr<Output> make_tcp_server_output(int port);
std::unique_ptr<Output> make_pty_output(const std::string& link);

}  // namespace plumb::wits_send
