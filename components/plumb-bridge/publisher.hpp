// The bridge's DDS side: raw and calibrated sensor batches, the status topic, and the latest
// calibration (from a file or from plumb/calibration, the newest wins).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "calibration_binding.hpp"
#include "plumb/bridge/counters.hpp"
#include "plumb/components/status_reporter.hpp"
#include "plumb/core/calibration_model.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::bridge_component {

struct PublisherOptions {
  std::string raw_topic;
  std::string calibrated_topic;
  std::string calibration_topic;  // empty: do not listen
  std::string status_topic;
  BindingRule binding;         // binding.tool_id is the tool id in the batches
  bool reliable = false;
  double g = 9.80665;          // the calibrated stream's |G| is checked against this
  double gravity_tolerance = 0.2;
};

class Publisher {
 public:
  using Log = std::function<void(const std::string&)>;
  Publisher(transport::Participant& participant, const PublisherOptions& options, bridge::Counters& counters, Log log);

  // Applies `model` from now on (false, logged in one line, when its coefficients are unusable or
  // bound to another tool or other units: docs/calibration.md "Binding").
  bool set_calibration(const CalibrationModel& model, const std::string& origin);
  // Takes new coefficients from the calibration topic, if any arrived.
  void poll_calibration();
  bool has_calibration() const { return calibration_.has_value(); }

  // One raw batch, and one calibrated batch when a calibration is known. Calibrated batches wait
  // until the first window passed the |G| check, and stop for good when one fails.
  void publish(const std::vector<Sample>& samples);
  // End of the stream: judges a window the check could not fill, releasing or dropping what waits.
  void finish();
  // A failed |G| check turns the state into "failed" with its reason.
  void publish_status(const std::string& state, const std::string& last_error);
  bool calibrated_stopped() const { return gravity_.verdict() == GravityCheck::Verdict::Failed; }

  std::size_t sensor_readers() const;

 private:
  PublisherOptions options_;
  bridge::Counters& c_;
  Log log_;
  transport::Writer<topics::SensorBatch> raw_;
  transport::Writer<topics::SensorBatch> calibrated_;
  components::StatusReporter status_;
  std::optional<transport::Reader<topics::CalibrationCoefficients>> calibration_reader_;
  void on_verdict(GravityCheck::Verdict before);
  std::optional<CalibrationModel> calibration_;
  std::string calibration_id_;
  GravityCheck gravity_;
  std::vector<topics::SensorBatch> held_;  // calibrated batches waiting for the first verdict
};

}  // namespace plumb::bridge_component
