// Everything the bridge counts: the parsers, the sample checks, the serial device and the
// publisher each add to their own fields; the status topic carries them all (docs/protocol.md
// "Counters" defines each one).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace plumb::bridge {

struct Counters {
  // Framing (binary mode).
  std::uint64_t frames_ok = 0;
  std::uint64_t crc_errors = 0;
  std::uint64_t truncated = 0;
  std::uint64_t bad_version = 0;
  std::uint64_t resyncs = 0;        // runs of discarded bytes
  std::uint64_t bytes_skipped = 0;  // bytes that were not part of a usable frame or line
  // ASCII line mode and CSV replay.
  std::uint64_t lines_ok = 0;
  std::uint64_t csv_errors = 0;
  // Sample checks.
  std::uint64_t seq_gaps = 0;
  std::uint64_t samples_missing = 0;
  std::uint64_t duplicates = 0;
  std::uint64_t seq_restarts = 0;
  std::uint64_t time_backwards = 0;
  std::uint64_t not_finite = 0;
  std::uint64_t out_of_range = 0;
  std::uint64_t saturated = 0;
  // Device.
  std::uint64_t opens = 0;
  std::uint64_t reopens = 0;
  std::uint64_t read_errors = 0;
  std::uint64_t bytes_read = 0;
  // Publishing.
  std::uint64_t samples_published = 0;
  std::uint64_t raw_batches = 0;
  std::uint64_t calibrated_batches = 0;
  std::uint64_t calibrations_applied = 0;
  std::uint64_t calibrations_rejected = 0;
  std::uint64_t calibrated_withheld = 0;  // samples not published calibrated: the |G| check failed
  std::uint64_t calibration_stamp_s = 0;  // stamp_s of the coefficients applied (0: none)

  // (name, value) for every counter, in the order above: the status topic's counters.
  std::vector<std::pair<std::string, std::uint64_t>> named() const;
  // Problems only (everything that means a byte or sample was not used as sent).
  std::uint64_t problems() const;
};

}  // namespace plumb::bridge
