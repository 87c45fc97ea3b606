// The CSV that plumb topic echo --csv and plumb export print: sensor batches as the sensor CSV of
// docs/conventions.md, any other message as its flattened fields.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "messages/fields.hpp"
#include "plumb/components/convert.hpp"
#include "plumb/csv/files.hpp"
#include "plumb/topics/all.hpp"

namespace plumb::cli {

// CSV rows of a message: its non-sequence fields, then one row per element of its sequence field
// (the samples of a sensor batch, the counters of a status) with the element's fields.
template <class M> std::vector<Flat> csv_rows(const M& m) {
  Flat base;
  std::vector<Flat> elements;
  topics::visit_fields(m, [&](const char* name, const auto& field) {
    using F = std::decay_t<decltype(field)>;
    if constexpr (is_vector<F>::value) {
      for (const auto& e : field) {
        Flat row;
        flatten(e, std::string(name) + ".", row);
        elements.push_back(std::move(row));
      }
    } else {
      if constexpr (is_array<F>::value) {
        for (std::size_t i = 0; i < field.size(); ++i) base.emplace_back(std::string(name) + "." + std::to_string(i), scalar_text(field[i]));
      } else if constexpr (std::is_class_v<F> && !std::is_same_v<F, std::string>) {
        flatten(field, std::string(name) + ".", base);
      } else {
        base.emplace_back(name, scalar_text(field));
      }
    }
  });
  if (elements.empty()) return {base};
  std::vector<Flat> rows;
  for (auto& e : elements) {
    Flat row = base;
    row.insert(row.end(), e.begin(), e.end());
    rows.push_back(std::move(row));
  }
  return rows;
}

inline std::string csv_escape(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// Sensor batches as the sensor CSV of docs/conventions.md (t, fx..bz, then gyros and temperature when the
// first batch carries them): a capture replays (plumb-bridge --replay) and estimates offline
// (plumb estimate) as it is.
class SensorCsvWriter {
 public:
  void write(std::ostream& out, const topics::SensorBatch& batch) {
    for (const auto& s : batch.samples) {
      const Sample sample = components::from_topic(s);
      if (!header_done_) {
        with_gyro_ = (sample.flags & flags::kHasGyro) != 0;
        with_temperature_ = (sample.flags & flags::kHasTemperature) != 0;
        csv::write_sensor_header(out, with_gyro_, with_temperature_);
        header_done_ = true;
      }
      csv::write_sensor_row(out, sample, with_gyro_, with_temperature_);
    }
  }

 private:
  bool header_done_ = false;
  bool with_gyro_ = false;
  bool with_temperature_ = false;
};

// Generic CSV of any other message: its flattened fields, one row per sequence element.
class FlatCsvWriter {
 public:
  template <class M> void write(std::ostream& out, const M& msg) {
    for (const auto& row : csv_rows(msg)) {
      if (!header_done_) {
        for (std::size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << row[i].first;
        out << '\n';
        header_done_ = true;
      }
      // A number not measured (NaN) is an empty cell, as in every plumb CSV.
      for (std::size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << (row[i].second == "nan" ? "" : csv_escape(row[i].second));
      out << '\n';
    }
  }

 private:
  bool header_done_ = false;
};

}  // namespace plumb::cli
