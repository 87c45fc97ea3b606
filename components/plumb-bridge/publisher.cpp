#include "publisher.hpp"

#include "plumb/components/calibration_convert.hpp"
#include "plumb/components/convert.hpp"

namespace plumb::bridge_component {
using components::calibration_problem;
using components::to_model;
namespace {
// About 2 s at 1 kHz in full batches: the first |G| window (100 usable samples) fills long before.
constexpr std::size_t kMaxHeldBatches = 64;

transport::Qos sensor_qos(bool reliable) {
  return reliable ? transport::Qos::reliable_stream() : transport::Qos::sensor_stream();
}
}  // namespace

Publisher::Publisher(transport::Participant& participant, const PublisherOptions& options, bridge::Counters& counters, Log log)
    : options_(options),
      c_(counters),
      log_(std::move(log)),
      raw_(transport::make_writer<topics::SensorBatch>(participant, options.raw_topic, sensor_qos(options.reliable))),
      calibrated_(transport::make_writer<topics::SensorBatch>(participant, options.calibrated_topic,
                                                              sensor_qos(options.reliable))),
      status_(participant, "plumb-bridge", 1.0, options.status_topic),
      gravity_(options.g, options.gravity_tolerance) {
  if (!options.calibration_topic.empty()) {
    calibration_reader_.emplace(transport::make_reader<topics::CalibrationCoefficients>(
        participant, options.calibration_topic, transport::Qos::calibration()));
  }
}

bool Publisher::set_calibration(const CalibrationModel& model, const std::string& origin) {
  if (const std::string bound = binding_problem(model, options_.binding); !bound.empty()) {
    ++c_.calibrations_rejected;
    log_(bound);
    return false;
  }
  const std::string problem = calibration_problem(model);
  if (!problem.empty()) {
    ++c_.calibrations_rejected;
    log_(describe_coefficients(model, origin) + " rejected: " + problem);
    return false;
  }
  calibration_ = model;
  calibration_id_ = components::bounded(model.calibration_id.empty() ? "unnamed" : model.calibration_id, topics::CalibrationCoefficients::kCalibrationIdMax);
  c_.calibration_stamp_s = model.stamp_s > 0 ? static_cast<std::uint64_t>(model.stamp_s) : 0;
  ++c_.calibrations_applied;
  // New coefficients are checked afresh: a units mismatch of the old ones says nothing about these.
  gravity_.reset();
  held_.clear();
  log_(describe_coefficients(model, origin) + " applied to tool '" + options_.binding.tool_id + "'" +
       (model.tool_id == options_.binding.tool_id ? "" : " (--calibration-any-tool)") + ": publishing " +
       options_.calibrated_topic + " once its |G| checks");
  return true;
}

void Publisher::poll_calibration() {
  if (!calibration_reader_) return;
  topics::CalibrationCoefficients m;
  std::optional<topics::CalibrationCoefficients> latest;
  // Only the newest message counts; set_calibration refuses it, in one line, when it is bound to
  // another tool (every bridge on the domain sees every tool's coefficients).
  while (calibration_reader_->take(m)) latest = m;
  if (latest) set_calibration(to_model(*latest), "topic " + options_.calibration_topic);
}

void Publisher::publish(const std::vector<Sample>& samples) {
  if (samples.empty()) return;
  topics::SensorBatch batch;
  batch.tool_id = components::bounded(options_.binding.tool_id, topics::Attitude::kToolIdMax);
  batch.samples.reserve(samples.size());
  for (const auto& s : samples) batch.samples.push_back(components::to_topic(s));
  raw_.write(batch);
  ++c_.raw_batches;
  c_.samples_published += samples.size();
  if (!calibration_) return;
  if (calibrated_stopped()) {
    c_.calibrated_withheld += samples.size();
    return;
  }
  batch.calibration_id = calibration_id_;
  batch.samples.clear();
  std::vector<Sample> calibrated(samples);
  for (Sample& s : calibrated) {
    calibration_->apply(s);
    batch.samples.push_back(components::to_topic(s));
  }
  const auto before = gravity_.verdict();
  gravity_.add(calibrated);
  held_.push_back(std::move(batch));
  if (held_.size() > kMaxHeldBatches) {  // a stream of unusable samples never fills the window
    c_.calibrated_withheld += held_.front().samples.size();
    held_.erase(held_.begin());
  }
  on_verdict(before);
}

void Publisher::finish() {
  if (!calibration_) return;
  const auto before = gravity_.verdict();
  gravity_.finish();
  on_verdict(before);
}

void Publisher::on_verdict(GravityCheck::Verdict before) {
  const auto now = gravity_.verdict();
  if (now == GravityCheck::Verdict::Pending) return;
  if (now == GravityCheck::Verdict::Failed) {
    for (const auto& b : held_) c_.calibrated_withheld += b.samples.size();
    held_.clear();
    if (before != now) log_(gravity_.reason() + " (calibration '" + calibration_id_ + "'; raw continues on " +
                            options_.raw_topic + ")");
    return;
  }
  for (const auto& b : held_) {
    calibrated_.write(b);
    ++c_.calibrated_batches;
  }
  held_.clear();
}

void Publisher::publish_status(const std::string& state, const std::string& last_error) {
  if (calibrated_stopped()) status_.publish("failed", c_.named(), gravity_.reason());
  else status_.publish(state, c_.named(), last_error);
}

std::size_t Publisher::sensor_readers() const { return raw_.matched_readers() + calibrated_.matched_readers(); }

}  // namespace plumb::bridge_component
