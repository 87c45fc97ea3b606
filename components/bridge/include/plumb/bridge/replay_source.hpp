// A sensor CSV (docs/conventions.md) replayed at its own pace ("realtime"), N times faster
// ("xN") or as fast as possible ("max"). Bad rows are counted (csv_errors) with an error naming
// line and column and the replay goes on, unless strict. Another logger's file is read through a
// csv::Import (its columns, units and axes), and the start of the file is checked for units that
// look wrong (csv::check_units) before the replay begins.
#pragma once

#include <fstream>
#include <functional>
#include <memory>
#include <optional>

#include "plumb/bridge/counters.hpp"
#include "plumb/bridge/source.hpp"
#include "plumb/csv/files.hpp"

namespace plumb::bridge {

class ReplaySource final : public SampleSource {
 public:
  // Throws csv::Error when the file cannot be opened or its header lacks a required column.
  // `on_bad_row` hears every bad row; with `strict`, poll() throws the csv::Error instead.
  // `on_warning` hears each csv::check_units finding, from within the constructor.
  ReplaySource(const std::string& path, double speed, Counters& counters, bool strict,
               std::function<void(const csv::Error&)> on_bad_row = {}, const csv::Import& import = {},
               const std::function<void(const std::string&)>& on_warning = {});
  bool poll(std::vector<Sample>& out, std::chrono::milliseconds max_wait) override;
  std::string describe() const override;
  bool healthy() const override { return true; }
  std::string last_error() const override { return last_error_; }

 private:
  bool read_next();  // into next_; false at end of file
  std::chrono::steady_clock::time_point due(double t) const;

  void check_units(const std::function<void(const std::string&)>& on_warning) const;

  std::string path_;
  csv::Import import_;
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
