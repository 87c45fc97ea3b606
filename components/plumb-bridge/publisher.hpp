// The bridge's DDS side: raw and calibrated sensor batches, the status topic, and the latest
// calibration (from a file or from plumb/calibration, the newest wins).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "plumb/bridge/counters.hpp"
#include "plumb/core/calibration_model.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::bridge {

struct PublisherOptions {
  std::string raw_topic;
  std::string calibrated_topic;
  std::string calibration_topic;  // empty: do not listen
  std::string status_topic;
  std::string tool_id;
  bool match_tool_id = false;  // accept only coefficients for tool_id (or with an empty tool id)
  bool reliable = false;
};

class Publisher {
 public:
  using Log = std::function<void(const std::string&)>;
  Publisher(transport::Participant& participant, const PublisherOptions& options, Counters& counters, Log log);

  // Applies `model` from now on (false, logged, when its coefficients are unusable).
  bool set_calibration(const CalibrationModel& model, const std::string& origin);
  // Takes new coefficients from the calibration topic, if any arrived.
  void poll_calibration();
  bool has_calibration() const { return calibration_.has_value(); }

  // One raw batch, and one calibrated batch when a calibration is known.
  void publish(const std::vector<Sample>& samples);
  void publish_status(const std::string& state, const std::string& last_error);

  std::size_t sensor_readers() const;

 private:
  PublisherOptions options_;
  Counters& c_;
  Log log_;
  transport::Writer<topics::SensorBatch> raw_;
  transport::Writer<topics::SensorBatch> calibrated_;
  transport::Writer<topics::ComponentStatus> status_;
  std::optional<transport::Reader<topics::CalibrationCoefficients>> calibration_reader_;
  std::optional<CalibrationModel> calibration_;
  std::string calibration_id_;
};

}  // namespace plumb::bridge
