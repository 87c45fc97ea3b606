// A field logger's clock: the time stamps it writes jitter (white, stamp_jitter_s rms) and run
// fast or slow against true time (clock_drift_ppm: +50 is a stamp 50 us ahead per second elapsed).
// Only the stamps err: the readings are those of the true instants, and the truth keeps true time.
// Off by default (the stream unchanged), and on its own random stream, so a run's sensor noise and
// its logger's dropouts do not depend on it. A jitter comparable to the interval puts some stamps
// before the one ahead of them, as a logger stamping on arrival would.
#pragma once

#include <cstdint>
#include <vector>

#include "plumb/core/sample.hpp"

namespace plumb::sim {

struct LoggerClock {
  double stamp_jitter_s = 0;   // rms of each stamp's own error (white)
  double clock_drift_ppm = 0;  // the stamps' rate error: elapsed stamp time = (1 + ppm 1e-6) x true time
};

// The stamps as the clock writes them: t' = t0 + (t - t0)(1 + ppm 1e-6) + jitter, t0 the first
// sample's time (the clock set right when the run starts). Throws std::invalid_argument for a
// setting that is not finite, a negative jitter, or a drift of 1e6 ppm or more.
std::vector<Sample> through_logger_clock(const std::vector<Sample>& samples, const LoggerClock& clock,
                                         std::uint64_t seed);

}  // namespace plumb::sim
