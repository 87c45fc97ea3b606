// Pseudo-terminals standing in for a sensor board's serial line: `plumb-sim --serial` writes
// frames into the master, the bridge reads the slave like a real serial device.
#pragma once

#include <cstddef>
#include <cstdint>
#include <chrono>
#include <string>

namespace plumb::bridge {

class PseudoTerminal {
 public:
  // Opens a new pty pair; the slave is set to raw mode and kept open by this object, so its
  // settings hold and the bridge may close and reopen it. Throws std::runtime_error.
  PseudoTerminal();
  ~PseudoTerminal();
  PseudoTerminal(const PseudoTerminal&) = delete;
  PseudoTerminal& operator=(const PseudoTerminal&) = delete;

  const std::string& slave_path() const { return slave_path_; }
  int master_fd() const { return master_; }

  // Writes all of `data` to the master, waiting while the line is full (a reader that is slow
  // or not there yet holds the writer up instead of losing bytes). False when the timeout ran
  // out first (only part was written) or the pty failed.
  bool write_all(const std::uint8_t* data, std::size_t size, std::chrono::milliseconds timeout);

  // Bytes written but not yet read by the slave's reader.
  std::size_t unread_bytes() const;
  // Waits until the reader has taken every byte written (true) or the timeout ran out (false).
  bool drain(std::chrono::milliseconds timeout) const;

  // Closes both ends: a reader of the slave sees the device disappear.
  void close();

 private:
  int master_ = -1;
  int slave_ = -1;
  std::string slave_path_;
};

// Points the symbolic link `link` at `target`, replacing an existing link atomically (rename of
// a temporary link). Throws std::runtime_error when `link` exists and is not a symbolic link.
void replace_symlink(const std::string& target, const std::string& link);
// Removes `link` if it is a symbolic link (never a regular file or device).
void remove_symlink(const std::string& link);

}  // namespace plumb::bridge
