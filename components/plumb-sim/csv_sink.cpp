#include "csv_sink.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "plumb/csv/files.hpp"

namespace plumb::sim_component {
namespace {

std::ofstream open_for_writing(const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  return out;
}

}  // namespace

CsvSink::CsvSink(const std::string& directory, const CsvColumns& columns) : directory_(directory), columns_(columns) {
  std::error_code ec;
  std::filesystem::create_directories(directory_, ec);
  if (ec) throw std::runtime_error("cannot create directory " + directory_ + ": " + ec.message());
  sensor_ = open_for_writing(std::filesystem::path(directory_) / "sensor.csv");
  truth_ = open_for_writing(std::filesystem::path(directory_) / "truth.csv");
  csv::write_sensor_header(sensor_, columns_.gyro, columns_.temperature, columns_.depth);
  csv::write_truth_header(truth_, columns_.position);
}

std::string CsvSink::describe() const { return directory_ + "/sensor.csv and truth.csv"; }

void CsvSink::write(const std::vector<Sample>& samples, const std::vector<TruthSample>& truth) {
  for (const auto& s : samples)
    csv::write_sensor_row(sensor_, s, columns_.gyro, columns_.temperature, columns_.depth);
  for (const auto& t : truth) csv::write_truth_row(truth_, t, columns_.position);
}

void CsvSink::finish(bool) {
  sensor_.flush();
  truth_.flush();
  if (!sensor_ || !truth_) throw std::runtime_error("writing " + directory_ + " failed (disk full?)");
}

}  // namespace plumb::sim_component
