#include "estimate/sample_input.hpp"

#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "plumb/components/convert.hpp"
#include "plumb/csv/files.hpp"
#include "recording/recording.hpp"

namespace plumb::cli {

std::string SampleInputSummary::describe(const std::string& path) const {
  std::string text = std::to_string(samples) + " samples from " + path;
  if (recording) text += " (" + topic + ")";
  if (bad_rows) text += " (" + std::to_string(bad_rows) + " bad rows skipped)";
  return text;
}

std::function<void(bool, const std::string&)> require_gyros_for(const estimator::Runner& runner, const std::string& path) {
  return [&runner, path](bool has_gyro, const std::string& what) {
    if (has_gyro) return;
    for (const auto& name : runner.needing_gyro())
      throw std::invalid_argument("estimator '" + name + "' needs gyros, and " + path + " has no " + what);
  };
}

int check_valid_estimates(const std::string& program, const estimator::Runner& runner) {
  int status = 0;
  for (const auto& slot : runner.slots()) {
    if (slot.estimates > slot.invalid) continue;
    std::cerr << program << ": " << slot.name << " made no valid estimate (";
    if (slot.estimates == 0) {
      std::cerr << "no estimate at all: too few samples for one window?";
    } else {
      std::cerr << "0 of " << slot.estimates << "; last reason: " << (slot.last_reason.empty() ? "none given" : slot.last_reason);
    }
    std::cerr << ")" << std::endl;
    status = 1;
  }
  return status;
}

SampleInputSummary read_samples(const SampleInput& input, const std::function<void(bool, const std::string&)>& on_start,
                                const std::function<void(const std::vector<Sample>&)>& on_chunk) {
  SampleInputSummary summary;
  summary.recording = is_recording(input.path);
  std::vector<Sample> chunk;
  bool started = false, units_checked = false;
  const auto push = [&] {
    // The first chunk is the start of the file: seconds of data, enough to tell g from m/s^2.
    if (!units_checked) {
      for (const auto& warning : csv::check_units(chunk, input.import)) std::cerr << input.program << ": warning: " << warning << '\n';
      units_checked = true;
    }
    on_chunk(chunk);
    chunk.clear();
  };
  const auto consume = [&](const Sample& s) {
    ++summary.samples;
    chunk.push_back(s);
    if (chunk.size() == 1024) push();
  };

  if (summary.recording) {
    summary.topic = read_recorded_batches(input.program, input.path, input.topic, [&](const topics::SensorBatch& batch) {
      if (!started && !batch.samples.empty()) {
        on_start(batch.samples.front().flags & topics::SAMPLE_HAS_GYRO, "gyro samples on its sensor topic");
        started = true;
      }
      for (const auto& s : batch.samples) consume(components::from_topic(s));
    });
  } else {
    if (!input.topic.empty())
      throw std::invalid_argument("--topic applies to a recording (.mcap); " + input.path + " is not one");
    std::ifstream in(input.path);
    if (!in) throw std::runtime_error("cannot open input '" + input.path + "'");
    csv::SensorReader reader(in, input.path, input.import);
    if (!csv::is_default(input.import))
      std::cerr << input.program << ": reading " << input.path << " with " << csv::describe(input.import) << '\n';
    on_start(reader.has_gyro(), "wx, wy, wz columns");
    started = true;
    while (true) {
      Sample s;
      try {
        if (!reader.next(s)) break;
      } catch (const csv::Error& e) {
        if (!input.skip_bad_rows) throw;
        ++summary.bad_rows;
        std::cerr << input.program << ": skipped " << e.what() << '\n';
        continue;
      }
      consume(s);
    }
  }
  if (!chunk.empty() || summary.samples == 0) push();
  return summary;
}

}  // namespace plumb::cli
