// What a field logger does to a clean sample stream: samples lost for a fraction of a second to a
// few seconds (a dropped link, a full buffer), and samples sent twice, either as an exact copy
// (the same stamp) or re-stamped on arrival (the same record, seq and content, a later stamp).
// The simulators write every sample once; this turns their stream into what a navigator is fed
// from a logger in the field. Off by default (no dropouts, no repeats: the stream unchanged), and
// on its own random stream, so a run's sensor noise does not depend on it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "plumb/core/sample.hpp"

namespace plumb::sim {

struct LoggerFaults {
  double dropouts_per_minute = 0;  // mean rate of dropouts (Poisson in time)
  double dropout_min_s = 0.1;      // each dropout's length, uniform in [min, max]
  double dropout_max_s = 3.0;
  double repeats_per_minute = 0;   // mean rate of samples sent twice
  bool repeats_restamped = false;  // false: the copy has the same stamp; true: stamped half a period later
};

// What was done, for tests: each dropout as the stamps of the samples before and after it.
struct LoggerFaultLog {
  struct Gap {
    double last_before = 0, first_after = 0;
    std::size_t lost = 0;
  };
  std::vector<Gap> gaps;
  std::size_t repeats = 0;
};

// Throws std::invalid_argument for a rate or length that is not finite, negative, or min > max.
std::vector<Sample> through_logger(const std::vector<Sample>& samples, const LoggerFaults& faults, double rate_hz,
                                   std::uint64_t seed, LoggerFaultLog* log = nullptr);

}  // namespace plumb::sim
