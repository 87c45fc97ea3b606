#include "plumb/bridge/counters.hpp"

namespace plumb::bridge {

std::vector<std::pair<std::string, std::uint64_t>> Counters::named() const {
  return {{"frames_ok", frames_ok},
          {"crc_errors", crc_errors},
          {"truncated", truncated},
          {"bad_version", bad_version},
          {"resyncs", resyncs},
          {"bytes_skipped", bytes_skipped},
          {"lines_ok", lines_ok},
          {"csv_errors", csv_errors},
          {"seq_gaps", seq_gaps},
          {"samples_missing", samples_missing},
          {"duplicates", duplicates},
          {"seq_restarts", seq_restarts},
          {"time_backwards", time_backwards},
          {"not_finite", not_finite},
          {"out_of_range", out_of_range},
          {"saturated", saturated},
          {"opens", opens},
          {"reopens", reopens},
          {"read_errors", read_errors},
          {"bytes_read", bytes_read},
          {"samples_published", samples_published},
          {"raw_batches", raw_batches},
          {"calibrated_batches", calibrated_batches},
          {"calibrations_applied", calibrations_applied},
          {"calibrations_rejected", calibrations_rejected},
          {"calibrated_withheld", calibrated_withheld},
          {"calibration_stamp_s", calibration_stamp_s}};
}

std::uint64_t Counters::problems() const {
  return crc_errors + truncated + bad_version + resyncs + csv_errors + seq_gaps + duplicates + seq_restarts +
         time_backwards + not_finite + out_of_range + saturated + read_errors;
}

}  // namespace plumb::bridge
