// A sensor CSV (shared CONVENTIONS.md) replayed at its own pace ("realtime"), N times faster
// ("xN") or as fast as possible ("max"). Bad rows are counted (csv_errors) with an error naming
// line and column and the replay goes on, unless strict.
#pragma once

#include <fstream>
#include <functional>
#include <memory>
#include <optional>

#include "plumb/bridge/counters.hpp"
#include "plumb/bridge/source.hpp"
#include "plumb/core/csv.hpp"

namespace plumb::bridge {

// "realtime" -> 1, "xN" or "N" -> N (> 0), "max" -> 0. Throws std::invalid_argument.
double parse_rate(const std::string& text);

class ReplaySource final : public SampleSource {
 public:
  // Throws csv::Error when the file cannot be opened or its header lacks a required column.
  // `on_bad_row` hears every bad row; with `strict`, poll() throws the csv::Error instead.
  ReplaySource(const std::string& path, double speed, Counters& counters, bool strict,
               std::function<void(const csv::Error&)> on_bad_row = {});
  bool poll(std::vector<Sample>& out, std::chrono::milliseconds max_wait) override;
  std::string describe() const override;
  bool healthy() const override { return true; }
  std::string last_error() const override { return last_error_; }

 private:
  bool read_next();  // into next_; false at end of file
  std::chrono::steady_clock::time_point due(double t) const;

  std::string path_;
  double speed_;
  Counters& c_;
  bool strict_;
  std::function<void(const csv::Error&)> on_bad_row_;
  std::ifstream file_;
  std::unique_ptr<csv::SensorReader> reader_;
  std::optional<Sample> next_;
  bool started_ = false;
  double t0_ = 0;
  std::chrono::steady_clock::time_point start_{};
  std::string last_error_;
};

}  // namespace plumb::bridge
