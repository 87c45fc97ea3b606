// A serial device read in termios raw mode that survives the device going away: on a read
// error, end of file or hang-up it closes the device and reopens it with exponential back-off,
// counting every reopen and keeping the last error.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "plumb/bridge/counters.hpp"

namespace plumb::bridge {

// The termios constant of a standard baud rate (50 .. 4000000); nullopt when not standard.
std::optional<unsigned> baud_constant(int baud);
// "9600, 19200, ..." for error messages.
std::string standard_baud_rates();

struct SerialOptions {
  std::string path;
  int baud = 115200;
  std::chrono::milliseconds backoff_min{100};
  std::chrono::milliseconds backoff_max{5000};
};

class SerialPort {
 public:
  enum class Event { None, Data, Opened, Closed, OpenFailed };
  struct ReadResult {
    std::size_t bytes = 0;
    Event event = Event::None;  // Closed: the stream ended (flush the parser); OpenFailed: will retry
  };

  // Counts into `counters` (opens, reopens, read_errors, bytes_read). Throws std::invalid_argument
  // for a baud rate that is not standard. Does not open yet.
  SerialPort(SerialOptions options, Counters& counters);
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // Opens the device when due, then waits up to `timeout` for bytes and reads what is there.
  ReadResult read(std::uint8_t* buffer, std::size_t capacity, std::chrono::milliseconds timeout);

  bool is_open() const { return fd_ >= 0; }
  const std::string& last_error() const { return last_error_; }
  std::chrono::milliseconds current_backoff() const { return backoff_; }
  void close();

 private:
  bool try_open();
  void fail(const std::string& what, bool count_as_read_error);

  SerialOptions options_;
  Counters& c_;
  unsigned speed_;
  int fd_ = -1;
  bool ever_opened_ = false;
  std::chrono::milliseconds backoff_;
  std::chrono::steady_clock::time_point next_attempt_{};
  std::string last_error_;
};

}  // namespace plumb::bridge
