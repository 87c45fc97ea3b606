#include "live_survey.hpp"

#include <cctype>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <set>

#include "plumb/components/convert.hpp"
#include "plumb/components/status_reporter.hpp"
#include "plumb/survey/detector_report.hpp"
#include "plumb/transport/topic_names.hpp"
#include "attitude_continuity.hpp"
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

// A topic name from a tool id: DDS names take letters, digits, '_' and '/'.
std::string topic_safe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  return s;
}

}  // namespace

int run_live_survey(const LiveOptions& o) {
  if (o.tool_id.empty()) throw std::invalid_argument("--tool-id is required: it names the tool surveyed and its topic");
  if (o.file.empty()) throw std::invalid_argument("--file is required: the survey is kept there across restarts");
  survey::Survey result(components::make_survey_options(o.survey, o.estimator));
  const double depth_sd = o.survey.depth_sd_m;
  const auto note = [](const std::string& n) { std::cerr << kProgram << ": " << n << std::endl; };
  SurveyStore store(o.file, result, note);

  auto conn = components::connect(o.transport, kProgram);
  const std::string survey_topic = transport::topic_names::survey(topic_safe(o.tool_id));
  const std::string attitude_topic = o.attitude_topic.empty() ? transport::topic_names::attitude(o.estimator) : o.attitude_topic;
  auto writer = transport::make_writer<topics::SurveyStation>(*conn.participant, survey_topic,
                                                               transport::default_qos_for_topic(survey_topic));
  auto attitude = transport::make_reader<topics::Attitude>(*conn.participant, attitude_topic, transport::Qos::attitude());
  auto depth = transport::make_reader<topics::MeasuredDepth>(
      *conn.participant, transport::topic_names::kDepth, transport::default_qos_for_topic(transport::topic_names::kDepth));
  components::StatusReporter status(*conn.participant, kProgram);
  components::install_stop_handler();

  // Stations the file already holds are published again: this writer is new, and late joiners get
  // the whole survey from it.
  for (const auto& row : result.rows()) {
    writer.write(to_topic(row));
    if (!o.quiet) print_row(row, "resumed station");
  }

  std::uint64_t refused = 0, depth_messages = 0, other_tool = 0;
  AttitudeContinuity continuity;
  std::string last_error;
  const auto on_station = [&](survey::Station s) {
    if (depth_sd >= 0) s.md_sd_m = depth_sd;
    try {
      const survey::SurveyRow& row = result.add(s);
      store.append(row);          // on disk (fsync'ed) before anyone is told
      writer.write(to_topic(row));
      if (!o.quiet) print_row(row, "station");
    } catch (const survey::StationError& e) {
      // Kept out of the geometry, but said and counted: never dropped in silence.
      ++refused;
      last_error = std::string("station refused: ") + e.what();
      note(last_error);
    }
  };
  survey::StationDetector detector(components::make_detector_options(o.survey), on_station, note);
  if (!result.rows().empty()) {
    const auto& last = result.rows().back().station;
    detector.resume(last.t_s, last.md_m, result.rows().size());
  }

  std::cerr << kProgram << ": " << conn.transport->name() << ", tool '" << o.tool_id << "': " << attitude_topic << " + "
            << transport::topic_names::kDepth << " -> " << survey_topic << ", file " << o.file << std::endl;
  const auto counters = [&] {
    const auto& c = detector.counters();
    return components::CounterList{{"stations", result.rows().size()},
                                   {"resumed_stations", store.resumed()},
                                   {"failed_qc", result.failed_qc()},
                                   {"refused_stations", refused},
                                   {"attitude_windows", c.windows},
                                   {"invalid_windows", c.invalid_windows},
                                   {"moving_windows", c.moving_windows},
                                   {"no_depth_windows", c.no_depth_windows},
                                   {"same_stop_windows", c.same_stop_windows},
                                   {"combined_windows", c.combined_windows},
                                   {"repeat_stops", c.repeat_stops},
                                   {"depth_messages", depth_messages},
                                   {"other_tool_messages", other_tool},
                                   {"attitude_gaps", continuity.gaps()},
                                   {"attitude_windows_missing", continuity.windows_missing()},
                                   {"readers", writer.matched_readers()}};
  };
  const auto t0 = Clock::now();
  const auto enough = [&] { return o.count > 0 && result.rows().size() >= static_cast<std::size_t>(o.count); };
  topics::Attitude a;
  topics::MeasuredDepth d;
  bool attitude_matched = false, depth_matched = false;
  // Until the first attitude of this tool: what the survey waits for, at 3 s, 6 s, 12 s..., with the
  // tool ids it hears instead (a --tool-id that no one publishes would otherwise wait in silence).
  bool heard_tool = false;
  auto last_attitude = Clock::now();
  std::set<std::string> other_tool_ids;
  double next_silence_note_s = 3;
  const auto other_tool_message = [&](const std::string& id) {
    ++other_tool;
    other_tool_ids.insert(id);
  };
  status.publish("running", counters());
  while (!components::g_stop && !enough()) {
    if (const double waited_s = std::chrono::duration<double>(Clock::now() - t0).count();
        !heard_tool && waited_s >= next_silence_note_s) {
      next_silence_note_s *= 2;
      std::string ids;
      for (const auto& id : other_tool_ids) ids += (ids.empty() ? "'" : ", '") + id + "'";
      note("no attitude for tool '" + o.tool_id + "' on " + attitude_topic + " for " + std::to_string(static_cast<int>(waited_s)) +
           " s (" + std::to_string(attitude.matched_writers()) + " writer(s) matched); " +
           (ids.empty() ? std::string("no other tool heard either") : "heard tool id(s) " + ids + " (choose with --tool-id)"));
    }
    // Said once each: an operator (or a test) knows the inputs are connected before the run starts.
    if (!attitude_matched && attitude.matched_writers() > 0) {
      attitude_matched = true;
      note("attitude writer matched on " + attitude_topic);
    }
    if (!depth_matched && depth.matched_writers() > 0) {
      depth_matched = true;
      note("depth writer matched on " + std::string(transport::topic_names::kDepth));
    }
    if (o.timeout_s > 0 && std::chrono::duration<double>(Clock::now() - t0).count() > o.timeout_s) {
      status.publish("failed", counters(), "timed out");
      components::print_error(kProgram, "timed out with " + std::to_string(result.rows().size()) + " of " +
                                            std::to_string(o.count) + " stations");
      return 1;
    }
    attitude.wait(std::chrono::milliseconds(100));
    // Depth first: a window is decided once the depth after its end is known.
    while (depth.take(d)) {
      if ((d.flags & topics::DEPTH_VALID) == 0) continue;
      if (!d.tool_id.empty() && d.tool_id != o.tool_id) {
        other_tool_message(d.tool_id);
        continue;
      }
      ++depth_messages;
      detector.add_depth(from_topic(d));
    }
    // The run ended (or the estimator stopped) during a stop: its station is due, not held forever.
    if (detector.stop_open() && Clock::now() - last_attitude > std::chrono::seconds(kSilenceFlushS)) detector.flush();
    while (attitude.take(a)) {
      last_attitude = Clock::now();
      if (!a.tool_id.empty() && a.tool_id != o.tool_id) {
        other_tool_message(a.tool_id);
        continue;
      }
      heard_tool = true;
      const Estimate e = components::from_topic(a);
      if (continuity.add(e.t_start, e.t_end) > 0) note(continuity.last_note());
      detector.add_attitude(e, a.tool_id);
    }
    if (status.due()) status.publish(refused ? "degraded" : "running", counters(), last_error);
  }
  // The stop in progress when asked to stop has its station now: its windows are all there are.
  if (!enough()) detector.flush();
  if (result.rows().empty()) note(survey::no_station_advice(detector.counters(), o.estimator, detector.still_tolerance_m()));
  status.publish("stopping", counters(), last_error);
  std::cerr << kProgram << ": " << result.rows().size() << " station(s) (" << store.resumed() << " resumed), "
            << result.failed_qc() << " failed QC, " << refused << " refused" << std::endl;
  if (enough()) components::sleep_while_running(o.linger_s);
  return 0;
}

}  // namespace plumb::survey_component
