#include "live.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "offline.hpp"
#include "plumb/calibration/procedures.hpp"
#include "plumb/calibration/triad_fit.hpp"
#include "plumb/components/convert.hpp"
#include "plumb/components/status_reporter.hpp"
#include "plumb/components/topic_wait.hpp"
#include "plumb/transport/topic_names.hpp"
#include "procedure.hpp"
#include "simulated_turntable.hpp"

namespace plumb::calibrate_component {

namespace {

struct Reading {  // one block of samples
  double t0 = 0, t1 = 0;
  Eigen::Matrix<double, 6, 1> mean = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> se = Eigen::Matrix<double, 6, 1>::Zero();
};

// Detects, from the stream's own timestamps, that the tool moved, then that it is still and
// settled, then records for a while: the live form of the station averaging's settling rule.
class StationDetector {
 public:
  StationDetector(int channels, double block_s, double record_s) : channels_(channels), block_s_(block_s), record_s_(record_s) {}

  enum class Event { None, Moved, Settled, Recorded };
  enum class Phase { WaitMove, WaitSettle, Record };

  Event push(const Sample& s) {
    if (block_.empty() || s.t - block_.front().t < block_s_) {
      block_.push_back(s);
      return Event::None;
    }
    const Reading r = close_block();
    block_.clear();
    block_.push_back(s);
    return on_reading(r);
  }

  void begin_station(bool first) {
    phase_ = first ? Phase::WaitSettle : Phase::WaitMove;
    readings_.clear();
  }
  double start_s() const { return start_s_; }
  double end_s() const { return end_s_; }
  // Raw accelerometer mean of the last reading of the station just recorded.
  Eigen::Vector3d recorded_accel() const { return last_station_.head<3>(); }

 private:
  Reading close_block() const {
    Reading r;
    const double n = static_cast<double>(block_.size());
    r.t0 = block_.front().t;
    r.t1 = block_.back().t;
    Eigen::Matrix<double, 6, 1> var = Eigen::Matrix<double, 6, 1>::Zero();
    for (const auto& s : block_) r.mean += (Eigen::Matrix<double, 6, 1>() << s.f, s.b).finished();
    r.mean /= n;
    for (const auto& s : block_) var += ((Eigen::Matrix<double, 6, 1>() << s.f, s.b).finished() - r.mean).cwiseAbs2();
    r.se = (var / std::max(1.0, n - 1) / n).cwiseSqrt();
    return r;
  }

  Eigen::Matrix<double, 6, 1> tolerance(const std::vector<Reading>& rs) const {
    Eigen::Matrix<double, 6, 1> tol;
    for (int c = 0; c < 6; ++c) {
      std::vector<double> se;
      for (const auto& r : rs) se.push_back(r.se[c]);
      std::nth_element(se.begin(), se.begin() + static_cast<long>(se.size() / 2), se.end());
      tol[c] = std::max(4.0 * se[se.size() / 2], 1e-12 * (1 + std::abs(rs.back().mean[c])));
    }
    return tol;
  }

  Event on_reading(const Reading& r) {
    switch (phase_) {
      case Phase::WaitMove: {
        // All six channels: a turn about the vertical (24 positions) barely changes the
        // accelerometers but turns the field.
        const auto d = (r.mean - last_station_).cwiseAbs();
        for (int c = 0; c < 6; ++c)
          if (d[c] > 20 * last_tol_[c]) {
            phase_ = Phase::WaitSettle;
            readings_.clear();
            return Event::Moved;
          }
        return Event::None;
      }
      case Phase::WaitSettle: {
        readings_.push_back(r);
        if (readings_.size() < 3) return Event::None;
        const std::vector<Reading> last(readings_.end() - 3, readings_.end());
        const auto tol = tolerance(last);
        for (int c = 0; c < channels_; ++c) {
          double lo = last[0].mean[c], hi = lo;
          for (const auto& x : last) lo = std::min(lo, x.mean[c]), hi = std::max(hi, x.mean[c]);
          if (hi - lo > tol[c]) return Event::None;
        }
        start_s_ = last.front().t0;
        record_until_ = last.back().t1 + record_s_;
        last_tol_ = tol;
        phase_ = Phase::Record;
        return Event::Settled;
      }
      case Phase::Record:
        if (r.t1 < record_until_) return Event::None;
        end_s_ = r.t1;
        last_station_ = r.mean;
        phase_ = Phase::WaitMove;
        return Event::Recorded;
    }
    return Event::None;
  }

  int channels_;
  double block_s_, record_s_;
  Phase phase_ = Phase::WaitSettle;
  std::vector<Sample> block_;
  std::vector<Reading> readings_;
  Eigen::Matrix<double, 6, 1> last_station_ = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> last_tol_ = Eigen::Matrix<double, 6, 1>::Zero();
  double start_s_ = 0, end_s_ = 0, record_until_ = 0;
};

std::string prompt(const calibration::Orientation& o) {
  if (!o.known()) return "turn the tool to a new orientation (spread the positions over all directions)";
  static const char* const kAxis[] = {"x", "y", "z"};
  std::string s = "put the tool with its " + std::string(kAxis[o.axis]) + " axis pointing " + (o.sign > 0 ? "UP" : "DOWN");
  if (o.rotation_deg) s += ", turntable at " + std::to_string(o.rotation_deg) + " deg";
  return s + " (" + o.label() + ")";
}

// The offline rule (check_orientations, same tolerance and message) applied to the stations
// recorded so far and this one: empty when it may be recorded, else why not.
std::string orientation_problem(std::vector<calibration::StationAverage>& recorded, const calibration::Station& st,
                                const Eigen::Vector3d& accel) {
  calibration::StationAverage candidate;
  candidate.station = st;
  candidate.accel = accel;
  std::vector<const calibration::StationAverage*> all;
  for (const auto& r : recorded) all.push_back(&r);
  all.push_back(&candidate);
  try {
    calibration::check_orientations(all, calibration::CommonOptions{}.max_orientation_error_deg);
  } catch (const calibration::CalibrationError& e) {
    return e.what();
  }
  recorded.push_back(candidate);
  return {};
}

// The position the detector just recorded: kept and the next one prompted, or refused by the
// orientation check (the operator puts the tool right and it is measured again).
void take_station(const std::vector<sim::StationPlan>& plans, int& index, StationDetector& detector,
                  std::vector<calibration::StationAverage>& checked, std::vector<calibration::Station>& stations,
                  std::atomic<int>& requested, std::atomic<int>& refused) {
  const int total = static_cast<int>(plans.size());
  const auto& plan = plans[static_cast<std::size_t>(index)];
  calibration::Station st;
  st.name = plan.name;
  st.start_s = detector.start_s();
  st.end_s = detector.end_s();
  st.orientation = calibration::parse_orientation(plan.orientation);
  st.run = plan.run;
  if (const auto problem = orientation_problem(checked, st, detector.recorded_accel()); !problem.empty()) {
    std::printf("      NOT RECORDED: %s\n[%d/%d] %s\n", problem.c_str(), index + 1, total, prompt(st.orientation).c_str());
    detector.begin_station(false);
    ++refused;  // the simulated operator, if any, corrects the position
    return;
  }
  stations.push_back(st);
  ++index;
  std::printf("      recorded %s [%.1f, %.1f] s (%d/%d done)\n", plan.name.c_str(), st.start_s, st.end_s, index, total);
  if (index < total) {
    std::printf("[%d/%d] %s\n", index + 1, total,
                prompt(calibration::parse_orientation(plans[static_cast<std::size_t>(index)].orientation)).c_str());
    detector.begin_station(false);
    requested = index;  // the simulated operator, if any, follows the prompt
  }
}

}  // namespace

int run_live(const Options& o) {
  const auto procedure = calibration::parse_procedure(o.procedure);
  auto plans = plans_for(o);
  if (procedure == calibration::Procedure::TwentyFourPosition) {
    plans.resize(24);  // one temperature run per live session
    for (auto& p : plans) p.run = o.run;
  }
  auto connection = components::connect(o.transport, "plumb-calibrate");
  auto reader = transport::make_reader<topics::SensorBatch>(*connection.participant, transport::topic_names::kSensorRaw,
                                                            transport::Qos::sensor_stream());
  components::StatusReporter status(*connection.participant, "plumb-calibrate");
  components::SilenceNotes silence("plumb-calibrate", transport::topic_names::kSensorRaw, connection.options.security.empty());
  std::uint64_t received = 0, unusable = 0;
  std::atomic<int> requested{0}, refused{0};
  const auto counters = [&](int recorded) {
    return components::CounterList{{"samples", received}, {"unusable_samples", unusable},
                                   {"positions_recorded", static_cast<std::uint64_t>(recorded)},
                                   {"positions_refused", static_cast<std::uint64_t>(refused.load())},
                                   {"positions_total", plans.size()}};
  };
  std::unique_ptr<SimulatedTurntable> turntable;
  if (o.simulate_turntable) turntable = std::make_unique<SimulatedTurntable>(o, plans, requested, refused);
  std::vector<calibration::StationAverage> checked;  // raw accelerometer means of the recorded stations

  const int channels = procedure == calibration::Procedure::Magnetometer ? 6 : 3;
  StationDetector detector(channels, 1.0, o.station_s);
  std::vector<Sample> samples;
  std::vector<calibration::Station> stations;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(o.timeout_s);
  const int total = static_cast<int>(plans.size());
  int index = 0;
  std::printf("plumb-calibrate: %s, %d positions, listening on %s\n", o.procedure.c_str(), total,
              transport::topic_names::kSensorRaw);
  std::printf("[1/%d] %s\n", total, prompt(calibration::parse_orientation(plans[0].orientation)).c_str());
  std::fflush(stdout);
  detector.begin_station(true);
  topics::SensorBatch batch;
  while (index < total) {
    if (status.due()) status.publish("running", counters(index));
    if (components::g_stop) throw std::runtime_error("stopped before the procedure ended; nothing published");
    if (std::chrono::steady_clock::now() > deadline)
      throw std::runtime_error("timed out after " + std::to_string(static_cast<int>(o.timeout_s)) + " s waiting for position " +
                               std::to_string(index + 1) + " (" + plans[static_cast<std::size_t>(index)].orientation +
                               "); nothing published");
    reader.wait(std::chrono::milliseconds(100));
    silence.check(*connection.participant, reader.matched_writers());
    while (index < total && reader.take(batch)) {
      silence.received();
      for (const auto& m : batch.samples) {
        const Sample s = components::from_topic(m);
        ++received;
        if ((s.flags & flags::kUnusable) || !s.f.allFinite()) {
          ++unusable;
          continue;
        }
        if (!samples.empty() && s.t <= samples.back().t) continue;  // late or repeated batch
        samples.push_back(s);
        const auto ev = detector.push(s);
        if (ev == StationDetector::Event::Moved) {
          std::printf("      moving... waiting for the tool to be still\n");
        } else if (ev == StationDetector::Event::Settled) {
          std::printf("      still and settled; recording %.0f s\n", o.station_s);
        } else if (ev == StationDetector::Event::Recorded) {
          take_station(plans, index, detector, checked, stations, requested, refused);
        }
        if (index >= total) break;
      }
      std::fflush(stdout);
    }
  }
  turntable.reset();
  status.publish("computing", counters(index));
  std::printf("all %d positions recorded; computing coefficients\n", total);
  const auto outcome = run_procedure(o, samples, stations);
  const int code = write_outputs(o, outcome);
  if (code == 0) publish_coefficients(o, outcome.result->model);
  return code;
}

}  // namespace plumb::calibrate_component
