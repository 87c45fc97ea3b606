// Checks every decoded sample before it is published: sequence numbers (gaps, duplicates,
// restarts), time going backwards, NaN/inf, saturated and out-of-range values. Flags the sample
// (plumb::flags) and counts; only duplicates are dropped (publishing them twice would corrupt
// the consumers' streams), everything else is published flagged.
#pragma once

#include <cstdint>

#include "plumb/bridge/counters.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::bridge {

// Per-triad limits, on the absolute value of each axis. A reading at or beyond the full scale
// is saturated (the sensor's rail); beyond the maximum it is physically impossible (out of range).
struct Limits {
  double accel_full_scale = 156.9;  // m/s^2 (16 g)
  double accel_max = 1000.0;
  double mag_full_scale = 200.0;    // microtesla
  double mag_max = 2000.0;
  double gyro_full_scale = 34.9;    // rad/s (2000 deg/s)
  double gyro_max = 100.0;
  double temp_min_c = -60.0;
  double temp_max_c = 260.0;
  // A sequence number up to this far behind the newest is a duplicate or stale repeat (dropped);
  // further behind, the board restarted (counted, kept).
  std::uint64_t duplicate_window = 64;
};

class SampleChecker {
 public:
  SampleChecker(Counters& counters, const Limits& limits = {}) : c_(counters), limits_(limits) {}
  // Flags `s` in place; false when it must be dropped (duplicate).
  bool check(Sample& s);
  // A new stream (device reopened): the next sample may come from a board that restarted, so a
  // sequence number not newer than the last one is a restart there, never a duplicate; a newer
  // one still shows the samples lost while the device was away as a gap.
  void new_stream() { new_stream_ = true; }

 private:
  Counters& c_;
  Limits limits_;
  bool have_last_ = false;
  bool new_stream_ = false;
  std::uint64_t last_seq_ = 0;
  double last_t_ = 0;
};

}  // namespace plumb::bridge
