#include "publisher.hpp"

#include "plumb/components/calibration_convert.hpp"
#include "plumb/components/convert.hpp"
#include "status.hpp"

namespace plumb::bridge {
using components::calibration_problem;
using components::to_model;
namespace {
transport::Qos sensor_qos(bool reliable) {
  return reliable ? transport::Qos::reliable_stream() : transport::Qos::sensor_stream();
}
}  // namespace

Publisher::Publisher(transport::Participant& participant, const PublisherOptions& options, Counters& counters, Log log)
    : options_(options),
      c_(counters),
      log_(std::move(log)),
      raw_(transport::make_writer<topics::SensorBatch>(participant, options.raw_topic, sensor_qos(options.reliable))),
      calibrated_(transport::make_writer<topics::SensorBatch>(participant, options.calibrated_topic,
                                                              sensor_qos(options.reliable))),
      status_(transport::make_writer<topics::ComponentStatus>(participant, options.status_topic,
                                                              transport::Qos::status())) {
  if (!options.calibration_topic.empty()) {
    calibration_reader_.emplace(transport::make_reader<topics::CalibrationCoefficients>(
        participant, options.calibration_topic, transport::Qos::calibration()));
  }
}

bool Publisher::set_calibration(const CalibrationModel& model, const std::string& origin) {
  const std::string problem = calibration_problem(model);
  if (!problem.empty()) {
    ++c_.calibrations_rejected;
    log_("calibration '" + model.calibration_id + "' from " + origin + " rejected: " + problem);
    return false;
  }
  calibration_ = model;
  calibration_id_ = components::bounded(model.calibration_id.empty() ? "unnamed" : model.calibration_id, topics::kIdMax);
  ++c_.calibrations_applied;
  log_("calibration '" + calibration_id_ + "' (tool '" + model.tool_id + "') from " + origin + " applied: publishing " +
       options_.calibrated_topic);
  return true;
}

void Publisher::poll_calibration() {
  if (!calibration_reader_) return;
  topics::CalibrationCoefficients m;
  std::optional<topics::CalibrationCoefficients> latest;
  while (calibration_reader_->take(m)) {
    if (options_.match_tool_id && !m.tool_id.empty() && m.tool_id != options_.tool_id) {
      ++c_.calibrations_rejected;
      log_("calibration '" + m.calibration_id + "' is for tool '" + m.tool_id + "', not '" + options_.tool_id +
           "': ignored");
      continue;
    }
    latest = m;
  }
  if (latest) set_calibration(to_model(*latest), "topic " + options_.calibration_topic);
}

void Publisher::publish(const std::vector<Sample>& samples) {
  if (samples.empty()) return;
  topics::SensorBatch batch;
  batch.tool_id = components::bounded(options_.tool_id, topics::kToolIdMax);
  batch.samples.reserve(samples.size());
  for (const auto& s : samples) batch.samples.push_back(components::to_topic(s));
  raw_.write(batch);
  ++c_.raw_batches;
  c_.samples_published += samples.size();
  if (!calibration_) return;
  batch.calibration_id = calibration_id_;
  batch.samples.clear();
  for (Sample s : samples) {
    calibration_->apply(s);
    batch.samples.push_back(components::to_topic(s));
  }
  calibrated_.write(batch);
  ++c_.calibrated_batches;
}

void Publisher::publish_status(const std::string& state, const std::string& last_error) {
  status_.write(make_status(c_, state, last_error));
}

std::size_t Publisher::sensor_readers() const { return raw_.matched_readers() + calibrated_.matched_readers(); }

}  // namespace plumb::bridge
