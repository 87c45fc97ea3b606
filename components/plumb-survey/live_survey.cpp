#include "live_survey.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>

#include "plumb/components/convert.hpp"
#include "plumb/components/status_reporter.hpp"
#include "plumb/components/topic_safe.hpp"
#include "plumb/survey/detector_report.hpp"
#include "plumb/transport/topic_names.hpp"
#include "attitude_continuity.hpp"
#include "clearance_watch.hpp"
#include "depth_clock.hpp"
#include "navigator_parameters.hpp"
#include "station_message.hpp"
#include "survey_store.hpp"

namespace plumb::survey_component {
namespace {

constexpr const char* kProgram = "plumb-survey";
constexpr int kSilenceFlushS = 3;  // attitude silence after which a stop in progress gets its station
using Clock = std::chrono::steady_clock;

void print_row(const survey::SurveyRow& r, const char* what) {
  std::printf("%s %u: MD %.3f m, I %.3f deg, A %.3f deg (%s), N %.3f E %.3f TVD %.3f m, DLS %.2f deg/30m, "
              "ellipse %.3f x %.3f m (1 sigma), QC %s%s%s\n",
              what, r.index, r.station.md_m, r.station.inclination_deg, r.azimuth_deg, survey::to_string(r.reference).c_str(),
              r.point.north_m, r.point.east_m, r.point.tvd_m, r.point.dls_deg_per_30m, r.uncertainty.major_sd_m,
              r.uncertainty.minor_sd_m, r.qc.pass ? "pass" : "FAIL", r.qc.pass ? "" : ": ", r.qc.reason.c_str());
  std::fflush(stdout);
}

}  // namespace

namespace {

void note(const std::string& n) { std::cerr << kProgram << ": " << n << std::endl; }

// A station-list offset well is surveyed with the survey's own reference field and latitude.
survey::StationListModel offset_model(const LiveOptions& o, const survey::SurveyOptions& s) {
  survey::StationListModel m;
  m.error_model = o.offset_error_model;
  if (s.field.gravity_mps2) m.gravity_mps2 = *s.field.gravity_mps2;
  if (s.field.total_b_uT) m.total_b_uT = *s.field.total_b_uT;
  if (s.field.dip_deg) m.dip_deg = *s.field.dip_deg;
  m.latitude_deg = s.latitude_deg;
  return m;
}

// The survey's own stations, surveyed again from a sidetrack's kick-off: through the survey's ISCWSA
// tool code (the navigator's own gyro model too) and reference field (none without an ISCWSA model:
// plumb's own propagation is not a tool code).
std::optional<survey::StationListModel> reference_model(const LiveOptions& o, const survey::SurveyOptions& s) {
  if (!s.tool_code) return std::nullopt;
  survey::StationListModel m = offset_model(o, s);
  m.error_model = s.tool_code->name;
  m.tool_code = s.tool_code;
  m.later_legs = s.later_legs;
  m.first_station_surveyed = true;
  return m;
}

// One live survey: its topics, the stations it has (kept in the file), what it has heard.
class LiveSurvey {
 public:
  LiveSurvey(const LiveOptions& o, components::Connection conn, std::optional<NavigatorParameterWatch> watch,
             const NavigatorAnswer& navigator)
      : o_(o),
        result_(components::make_survey_options(o.survey, o.estimator,
                                                navigator.parameters ? &*navigator.parameters : nullptr)),
        error_model_said_(navigator.said),
        error_model_status_(navigator.status),
        store_(o.file, result_, note),
        conn_(std::move(conn)),
        watch_(std::move(watch)),
        survey_topic_(transport::topic_names::survey(components::topic_safe(o.tool_id))),
        attitude_topic_(o.attitude_topic.empty() ? transport::topic_names::attitude(o.estimator) : o.attitude_topic),
        writer_(transport::make_writer<topics::SurveyStation>(*conn_.participant, survey_topic_,
                                                               transport::default_qos_for_topic(survey_topic_))),
        attitude_(transport::make_reader<topics::Attitude>(*conn_.participant, attitude_topic_, transport::Qos::attitude())),
        depth_(transport::make_reader<topics::MeasuredDepth>(*conn_.participant, transport::topic_names::kDepth,
                                                             transport::default_qos_for_topic(transport::topic_names::kDepth))),
        status_(*conn_.participant, kProgram),
        clock_(clock_options(o)),
        detector_(components::make_detector_options(o.survey), [this](survey::Station st) { on_station(st); }, note),
        clearance_(o.clearance, offset_model(o, result_.options()), reference_model(o, result_.options()),
                   result_.options().reference, note) {
    if (error_model_fallback()) last_error_ = error_model_status_;
    if (clearance_.active())
      clearance_writer_.emplace(transport::make_writer<topics::Clearance>(
          *conn_.participant, transport::topic_names::kClearance,
          transport::default_qos_for_topic(transport::topic_names::kClearance)));
  }

  int run() {
    components::install_stop_handler();
    republish_resumed();
    std::cerr << kProgram << ": " << conn_.transport->name() << ", tool '" << o_.tool_id << "': " << attitude_topic_
              << " + " << transport::topic_names::kDepth << " -> " << survey_topic_ << ", file " << o_.file << std::endl;
    if (!clock_.given())
      sensors_.emplace(transport::make_reader<topics::SensorBatch>(*conn_.participant, o_.sensor_topic,
                                                                   transport::Qos::sensor_stream()));
    note(clock_.describe() + (clock_.given() ? "" : "; matching the stops on " + o_.sensor_topic + " with the depth's"));
    if (!error_model_said_.empty()) note(error_model_said_);
    note("error model " + survey::error_model_text(result_.options()) +
         (result_.options().station_sigma_beyond_model ? ": each station's own sigma counts by its excess over the model's"
                                                       : ""));
    clock_said_ = clock_.given();  // said once above; an estimate is said when it comes
    t0_ = Clock::now();
    last_attitude_ = Clock::now();
    status_.publish(state(), all_counters(), status_message());
    while (!components::g_stop && !enough()) {
      say_what_it_waits_for();
      if (watch_)
        if (const auto changed = watch_->change()) navigator_changed(*changed);
      if (o_.timeout_s > 0 && std::chrono::duration<double>(Clock::now() - t0_).count() > o_.timeout_s) {
        status_.publish("failed", all_counters(), "timed out");
        components::print_error(kProgram, "timed out with " + std::to_string(result_.rows().size()) + " of " +
                                              std::to_string(o_.count) + " stations");
        return 1;
      }
      attitude_.wait(std::chrono::milliseconds(100));
      take_sensors();
      take_depths();  // first: a window is decided once the depth after its end is known
      // The run ended (or the estimator stopped) during a stop: its station is due, not held forever.
      if (detector_.stop_open() && Clock::now() - last_attitude_ > std::chrono::seconds(kSilenceFlushS)) detector_.flush();
      take_attitudes();
      if (status_.due()) status_.publish(state(), all_counters(), status_message());
    }
    // The stop in progress when asked to stop has its station now: its windows are all there are.
    if (!enough()) detector_.flush();
    if (result_.rows().empty()) {
      note(survey::no_station_advice(detector_.counters(), o_.estimator, detector_.still_tolerance_m()));
      note(clock_.describe());
    }
    status_.publish("stopping", all_counters(), status_message());
    std::cerr << kProgram << ": " << result_.rows().size() << " station(s) (" << store_.resumed() << " resumed), "
              << result_.failed_qc() << " failed QC, " << refused_ << " refused" << std::endl;
    if (enough()) components::sleep_while_running(o_.linger_s);
    return 0;
  }

 private:
  // Stations the file already holds are published again: this writer is new, and late joiners get
  // the whole survey from it. The detector goes on after the last of them.
  void republish_resumed() {
    for (const auto& row : result_.rows()) {
      writer_.write(to_topic(row, result_.section_azimuth_deg()));
      if (!o_.quiet) print_row(row, "resumed station");
      publish_clearance(row);
    }
    if (!result_.rows().empty()) {
      const auto& last = result_.rows().back().station;
      detector_.resume(last.t_s, last.md_m, result_.rows().size());
    }
  }

  static DepthClockOptions clock_options(const LiveOptions& o) {
    DepthClockOptions c;
    c.offset_s = o.depth_clock_offset_s;
    c.drift_ppm = o.depth_clock_drift_ppm;
    if (o.survey.still_tolerance_m > 0) c.still_tolerance_m = o.survey.still_tolerance_m;
    return c;
  }

  void on_station(survey::Station s) {
    if (o_.survey.depth_sd_m >= 0) s.md_sd_m = o_.survey.depth_sd_m;
    try {
      // The file says, before the rows that used it, how the depth's clock was brought to the sensors'.
      if (const std::string line = clock_.describe(); line != clock_in_file_) {
        store_.comment(line);
        clock_in_file_ = line;
      }
      const survey::SurveyRow& row = result_.add(s);
      store_.append(row);  // on disk (fsync'ed) before anyone is told
      writer_.write(to_topic(row, result_.section_azimuth_deg()));
      if (!o_.quiet) print_row(row, "station");
      const auto level = clearance_.level();
      publish_clearance(row);
      // A new level is on plumb/status at once, not at the next period.
      if (clearance_.level() != level) status_.publish(state(), all_counters(), status_message());
    } catch (const survey::StationError& e) {
      // Kept out of the geometry, but said and counted: never dropped in silence.
      ++refused_;
      last_error_ = std::string("station refused: ") + e.what();
      note(last_error_);
    }
  }

  // Every offset well against the survey's newest station, on plumb/clearance.
  void publish_clearance(const survey::SurveyRow& row) {
    if (!clearance_writer_) return;
    for (const auto& pair : clearance_.at_station(row)) clearance_writer_->write(to_topic(pair, row, clearance_.levels()));
  }

  // Degraded: stations refused, the newest station at the clearance alarm, or the navigator's error
  // model replaced by plumb's own terms (its host wrote no parameters).
  std::string state() const {
    return refused_ > 0 || error_model_fallback() || clearance_.level() == survey::ClearanceLevel::Alarm ? "degraded"
                                                                                                        : "running";
  }
  // The clearance while not clear comes first: it is what the driller must see.
  std::string status_message() const {
    return clearance_.status_line().empty() ? last_error_ : clearance_.status_line();
  }

  components::CounterList counters() const {
    const auto& c = detector_.counters();
    return components::CounterList{{"stations", result_.rows().size()},
                                   {"resumed_stations", store_.resumed()},
                                   {"failed_qc", result_.failed_qc()},
                                   {"refused_stations", refused_},
                                   {"attitude_windows", c.windows},
                                   {"invalid_windows", c.invalid_windows},
                                   {"moving_windows", c.moving_windows},
                                   {"no_depth_windows", c.no_depth_windows},
                                   {"same_stop_windows", c.same_stop_windows},
                                   {"combined_windows", c.combined_windows},
                                   {"repeat_stops", c.repeat_stops},
                                   {"depth_messages", depth_messages_},
                                   {"other_tool_messages", other_tool_},
                                   {"attitude_gaps", continuity_.gaps()},
                                   {"attitude_windows_missing", continuity_.windows_missing()},
                                   {"readers", writer_.matched_readers()},
                                   {"error_model_fallback", error_model_fallback() ? 1u : 0u}};
  }

  components::CounterList all_counters() {
    auto list = counters();
    for (auto& c : clock_.counters()) list.push_back(c);
    for (auto& c : clearance_.counters()) list.push_back(c);
    return list;
  }

  bool enough() const { return o_.count > 0 && result_.rows().size() >= static_cast<std::size_t>(o_.count); }

  // Until the first attitude of this tool: what the survey waits for, at 3 s, 6 s, 12 s..., with the
  // tool ids it hears instead (a --tool-id that no one publishes would otherwise wait in silence).
  // Each input's match is said once: an operator (or a test) knows they are connected.
  void say_what_it_waits_for() {
    if (const double waited_s = std::chrono::duration<double>(Clock::now() - t0_).count();
        !heard_tool_ && waited_s >= next_silence_note_s_) {
      next_silence_note_s_ *= 2;
      std::string ids;
      for (const auto& id : other_tool_ids_) ids += (ids.empty() ? "'" : ", '") + id + "'";
      note("no attitude for tool '" + o_.tool_id + "' on " + attitude_topic_ + " for " +
           std::to_string(static_cast<int>(waited_s)) + " s (" + std::to_string(attitude_.matched_writers()) +
           " writer(s) matched); " +
           (ids.empty() ? std::string("no other tool heard either") : "heard tool id(s) " + ids + " (choose with --tool-id)"));
    }
    if (!attitude_matched_ && attitude_.matched_writers() > 0) {
      attitude_matched_ = true;
      note("attitude writer matched on " + attitude_topic_);
    }
    if (!depth_matched_ && depth_.matched_writers() > 0) {
      depth_matched_ = true;
      note("depth writer matched on " + std::string(transport::topic_names::kDepth));
    }
  }

  void other_tool_message(const std::string& id) {
    ++other_tool_;
    other_tool_ids_.insert(id);
  }

  void take_depths() {
    topics::MeasuredDepth d;
    while (depth_.take(d)) {
      if ((d.flags & topics::DEPTH_VALID) == 0) continue;
      if (!d.tool_id.empty() && d.tool_id != o_.tool_id) {
        other_tool_message(d.tool_id);
        continue;
      }
      ++depth_messages_;
      clock_.add_depth(from_topic(d));
    }
    for (const auto& r : clock_.take_aligned()) {
      // A refined alignment must not send the detector back in time.
      if (r.t_s <= last_aligned_t_) continue;
      last_aligned_t_ = r.t_s;
      detector_.add_depth(r);
    }
    say_clock();
  }

  // The alignment, said when it first comes and when another stop refines it.
  void say_clock() {
    const auto& a = clock_.alignment();
    const std::size_t stops = a ? a->matched : 0;
    if (a.has_value() == clock_said_ && stops == clock_stops_said_) return;
    clock_said_ = a.has_value();
    clock_stops_said_ = stops;
    note(clock_.describe());
  }

  void take_sensors() {
    if (!sensors_) return;
    topics::SensorBatch batch;
    while (sensors_->take(batch)) {
      if (!batch.tool_id.empty() && batch.tool_id != o_.tool_id) continue;
      for (const auto& s : batch.samples) clock_.add_sensor(components::from_topic(s));
    }
  }

  void take_attitudes() {
    topics::Attitude a;
    while (attitude_.take(a)) {
      last_attitude_ = Clock::now();
      if (!a.tool_id.empty() && a.tool_id != o_.tool_id) {
        other_tool_message(a.tool_id);
        continue;
      }
      heard_tool_ = true;
      const Estimate e = components::from_topic(a);
      if (continuity_.add(e.t_start, e.t_end) > 0) note(continuity_.last_note());
      detector_.add_attitude(e, a.tool_id);
    }
  }

  const LiveOptions& o_;
  survey::Survey result_;
  // auto on the navigator's stations without its parameters: plumb's own terms, said on status.
  bool error_model_fallback() const { return !error_model_status_.empty(); }
  // A change of the navigator's parameters configures it afresh and it aligns again
  // (docs/components.md): a new gyro run, so the stations below are a survey leg of their own
  // through the new figures; those above keep what they were published with.
  void navigator_changed(const NavigatorParameterWatch::Change& c) {
    const std::string restart = "restart plumb-survey to survey through the host's (a restart surveys the file's "
                                "stations again, all through the host's figures then)";
    if (!c.now) return note(c.said + ": this survey goes on through the model it has; " + restart);
    if (error_model_fallback()) return note(c.said + ": this survey goes on through plumb's own terms; " + restart);
    const survey::SurveyOptions next = components::make_survey_options(o_.survey, o_.estimator, &*c.now);
    const survey::iscwsa::ToolCode& tool = *next.tool_code;
    result_.start_leg(tool);
    clearance_.start_leg(tool);
    const auto& rows = result_.rows();
    char md[32];
    std::snprintf(md, sizeof md, "%.2f", rows.empty() ? 0.0 : rows.back().station.md_m);
    std::string line = c.said + ": the navigator aligns again, a new gyro run, so the survey goes on in a new leg " +
                       (rows.empty() ? std::string("from its first station") : std::string("below MD ") + md + " m") +
                       " through its new figures (" + tool.name + ", systematic errors a draw of their own); the " +
                       std::to_string(rows.size()) + " station(s) above keep theirs";
    if (next.latitude_deg != result_.options().latitude_deg && !std::isnan(result_.options().latitude_deg)) {
      char lat[32];
      std::snprintf(lat, sizeof lat, "%g", result_.options().latitude_deg);
      line += "; the well's latitude stays " + std::string(lat) + " deg for the whole survey (--latitude, or a restart)";
    }
    note(line);
  }
  std::string error_model_said_, error_model_status_;
  SurveyStore store_;
  components::Connection conn_;
  std::optional<NavigatorParameterWatch> watch_;  // the navigator's parameters as its host writes them (auto)
  std::string survey_topic_, attitude_topic_;
  transport::Writer<topics::SurveyStation> writer_;
  transport::Reader<topics::Attitude> attitude_;
  transport::Reader<topics::MeasuredDepth> depth_;
  components::StatusReporter status_;
  DepthClock clock_;
  std::optional<transport::Reader<topics::SensorBatch>> sensors_;
  std::string clock_in_file_;
  double last_aligned_t_ = -1e300;
  bool clock_said_ = false;
  std::size_t clock_stops_said_ = 0;
  survey::StationDetector detector_;
  ClearanceWatch clearance_;
  std::optional<transport::Writer<topics::Clearance>> clearance_writer_;
  AttitudeContinuity continuity_;
  std::uint64_t refused_ = 0, depth_messages_ = 0, other_tool_ = 0;
  std::string last_error_;
  Clock::time_point t0_, last_attitude_;
  bool attitude_matched_ = false, depth_matched_ = false, heard_tool_ = false;
  std::set<std::string> other_tool_ids_;
  double next_silence_note_s_ = 3;
};

}  // namespace

int run_live_survey(const LiveOptions& o) {
  if (o.tool_id.empty()) throw std::invalid_argument("--tool-id is required: it names the tool surveyed and its topic");
  if (o.file.empty()) throw std::invalid_argument("--file is required: the survey is kept there across restarts");
  DepthClockOptions clock;
  clock.offset_s = o.depth_clock_offset_s;
  clock.drift_ppm = o.depth_clock_drift_ppm;
  check_depth_clock_options(clock);  // before joining the network: a usage error is said at once
  components::check_clearance_options(o.clearance);
  const bool navigator_model = o.survey.error_model == "auto" && o.estimator == components::kNavigatorPlugin;
  if (!o.clearance.sidetracks.empty() && !navigator_model)
    ClearanceWatch::check_sidetracks(o.clearance, components::make_survey_options(o.survey, o.estimator).tool_code.has_value());
  // The navigator's own gyro model needs its parameters: read from its host before the survey
  // starts (the file's stations are resumed through the same model).
  components::Connection conn = components::connect(o.transport, kProgram);
  std::optional<NavigatorParameterWatch> watch;
  NavigatorAnswer navigator;
  if (navigator_model) {
    components::install_stop_handler();
    const std::string host = o.estimator_host.empty() ? components::host_name() : o.estimator_host;
    char wait[32];
    std::snprintf(wait, sizeof wait, "%g", o.estimator_wait_s);
    note("error model: reading the " + o.estimator + " navigator's parameters from estimator host '" + host + "' (up to " +
         wait + " s)");
    watch.emplace(conn, host, o.estimator);
    navigator = watch->first(o.estimator_wait_s);
    // Plumb's own terms are no tool code to survey the well drilled again through from a kick-off.
    if (!o.clearance.sidetracks.empty() && !navigator.parameters)
      throw std::invalid_argument("--sidetrack with --error-model auto surveys the well drilled again through the "
                                  "navigator's gyro model, which needs its parameters: " + navigator.why +
                                  " (--estimator-host names the host that runs the navigator; --error-model "
                                  "GYRO:tactical, GYRO:mems or a tool code file names a model)");
  }
  LiveSurvey survey(o, std::move(conn), std::move(watch), navigator);
  return survey.run();
}

}  // namespace plumb::survey_component
