// Writes DIR/sensor.csv and DIR/truth.csv (CONVENTIONS.md "Files") instead of publishing.
#pragma once

#include <fstream>
#include <string>

#include "sink.hpp"

namespace plumb::sim_component {

class CsvSink final : public Sink {
 public:
  // Creates DIR if needed; throws std::runtime_error when the files cannot be opened.
  CsvSink(const std::string& directory, bool with_gyro);
  std::string describe() const override;
  void write(const std::vector<Sample>& samples, const std::vector<TruthSample>& truth) override;
  void finish(bool interrupted) override;
  bool paced() const override { return false; }

 private:
  std::string directory_;
  bool with_gyro_;
  std::ofstream sensor_, truth_;
};

}  // namespace plumb::sim_component
