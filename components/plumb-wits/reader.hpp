// plumb-wits's loop: bytes from the link, frames from the parser, depths from the decoder, each
// depth on plumb/depth as it comes, the counters on plumb/status once a second, the log.
#pragma once

#include <string>

#include "plumb/components/cli.hpp"
#include "plumb/wits/depth_decoder.hpp"
#include "plumb/wits/link.hpp"

namespace plumb::wits_component {

inline constexpr const char* kProgram = "plumb-wits";

struct ReaderOptions {
  components::TransportOptions transport;
  std::string listen;   // [ADDRESS:]PORT: TCP server
  std::string connect;  // HOST:PORT: TCP client
  std::string device;   // serial port
  int baud = 9600;
  std::string tool_id = "board";
  wits::DepthOptions depth;
  double depth_sd_m = 0;
  double silence_notice_s = 10;  // connected but no frame this long: say so
  double wait_subscribers_s = 5;  // a bounded wait for a reader, so that the first depth is not lost
  long long count = 0;           // exit after this many depths published (0: until stopped)
  double linger_s = 1;
  wits::Backoff backoff;
};

// Runs until stopped (SIGINT/SIGTERM) or --count; returns the exit status. Throws for what stops
// it before it runs (a port that cannot be bound, DDS).
int run_reader(const ReaderOptions& options);

}  // namespace plumb::wits_component
