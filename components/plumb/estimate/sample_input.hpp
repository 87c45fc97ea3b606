// The samples of a sensor CSV (plumb's format, or another logger's through --column/--units/--axes)
// or of a recording (MCAP, plumb record), streamed in chunks: what plumb estimate and plumb compare
// read. 10 minutes at 10 kHz are 6 million samples, so nothing holds the whole input.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "plumb/core/sample.hpp"
#include "plumb/csv/import.hpp"
#include "plumb/estimator/runner.hpp"

namespace plumb::cli {

struct SampleInput {
  std::string program;   // "plumb estimate": the prefix of its stderr lines
  std::string path;
  std::string topic;     // of a recording; empty: the one sensor topic it has
  csv::Import import;    // of a CSV
  bool skip_bad_rows = false;
};

struct SampleInputSummary {
  std::size_t samples = 0, bad_rows = 0;
  bool recording = false;
  std::string topic;  // the recording's topic read
  // "12000 samples from run.mcap (plumb/sensor/calibrated)", with bad rows when some were skipped
  std::string describe(const std::string& path) const;
};

// Calls `on_start(has_gyro, what)` once before the first chunk (`what` names what is missing when
// has_gyro is false, such as "wx, wy, wz columns"), then `on_chunk` with up to 1024 samples at a
// time, oldest first; the first chunk's units are checked and warnings printed. Throws
// std::invalid_argument and std::runtime_error with one-line messages.
SampleInputSummary read_samples(const SampleInput& input, const std::function<void(bool has_gyro, const std::string& what)>& on_start,
                                const std::function<void(const std::vector<Sample>&)>& on_chunk);

// An on_start for read_samples that refuses an input without gyros when a plugin of `runner` needs
// them: "estimator 'strapdown' needs gyros, and run.csv has no wx, wy, wz columns".
std::function<void(bool, const std::string&)> require_gyros_for(const estimator::Runner& runner, const std::string& path);

// After a run: one stderr line for each plugin of `runner` that made no valid estimate at all,
// "plumb estimate: compensated made no valid estimate (0 of 12; last reason: ...)"; returns 1 when
// there was such a plugin (the run's exit status), else 0.
int check_valid_estimates(const std::string& program, const estimator::Runner& runner);

}  // namespace plumb::cli
