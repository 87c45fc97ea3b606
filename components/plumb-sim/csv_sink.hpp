// Writes DIR/sensor.csv and DIR/truth.csv (docs/conventions.md "Files") instead of publishing.
#pragma once

#include <fstream>
#include <string>

#include "sink.hpp"

namespace plumb::sim_component {

// Optional columns: the platform writes gyros (unless --no-gyro) and temperature; a drilling run
// writes gyros, depth_m (and temp_c with --circulation-temp) in sensor.csv and the position columns
// in truth.csv.
struct CsvColumns {
  bool gyro = true;
  bool temperature = true;
  bool depth = false;
  bool position = false;
};

class CsvSink final : public Sink {
 public:
  // Creates DIR if needed; throws std::runtime_error when the files cannot be opened.
  CsvSink(const std::string& directory, const CsvColumns& columns);
  CsvSink(const std::string& directory, bool with_gyro) : CsvSink(directory, CsvColumns{with_gyro, true, false, false}) {}
  std::string describe() const override;
  void write(const std::vector<Sample>& samples, const std::vector<TruthSample>& truth) override;
  void finish(bool interrupted) override;
  bool paced() const override { return false; }
  bool carries_depth() const override { return columns_.depth; }

 private:
  std::string directory_;
  CsvColumns columns_;
  std::ofstream sensor_, truth_;
};

}  // namespace plumb::sim_component
