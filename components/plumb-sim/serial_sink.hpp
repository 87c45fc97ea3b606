// `plumb-sim --serial PATH`: writes the sensor board's wire protocol (docs/protocol.md) into a
// pseudo-terminal whose slave is linked at PATH, so `plumb-bridge --device PATH` reads the
// simulated platform like real hardware. If PATH is an existing serial device, writes there.
#pragma once

#include <memory>
#include <string>

#include "plumb/bridge/pty.hpp"
#include "sink.hpp"

namespace plumb::sim_component {

struct SerialSinkOptions {
  std::string path;
  int baud = 921600;           // for a real device; a pseudo-terminal ignores it
  std::string mode = "binary"; // binary frames or ascii lines
  double write_timeout_s = 5;  // a reader that does not read for this long: frames are dropped, counted
};

class SerialSink final : public Sink {
 public:
  // Throws std::runtime_error / std::invalid_argument when the pty or device cannot be set up.
  explicit SerialSink(const SerialSinkOptions& options);
  ~SerialSink() override;
  std::string describe() const override;
  void write(const std::vector<Sample>& samples, const std::vector<TruthSample>& truth) override;
  void finish(bool interrupted) override;
  std::uint64_t messages() const override { return frames_; }

 private:
  bool write_bytes(const std::vector<std::uint8_t>& bytes);

  SerialSinkOptions options_;
  std::unique_ptr<bridge::PseudoTerminal> pty_;
  int device_fd_ = -1;  // when PATH is a real device
  bool header_sent_ = false;
  bool reader_absent_ = false;  // the last write timed out: write without waiting until one succeeds
  std::uint64_t frames_ = 0;
  std::uint64_t dropped_ = 0;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace plumb::sim_component
