// plumb-survey: the survey, live. Reads one tool's attitude (plumb/attitude/<estimator>) and the
// rig's measured depth (plumb/depth), takes a station at every stop, checks it against the
// reference field, places it by minimum curvature with its uncertainty, keeps it in the survey file
// and publishes it on plumb/survey/<tool> (reliable, transient-local, keep-all: late joiners get
// every station). Restarted, it resumes from the file. docs/surveys.md.
#include "live_survey.hpp"

int main(int argc, char** argv) {
  using namespace plumb;
  survey_component::LiveOptions o;
  CLI::App app{"plumb-survey: survey stations live from an attitude topic and plumb/depth; publishes plumb/survey/<tool> "
               "and keeps the survey in a file across restarts"};
  app.name("plumb-survey");
  components::add_transport_options(app, o.transport);
  app.add_option("--tool-id", o.tool_id, "tool surveyed (its attitude and depth messages); names plumb/survey/<tool>")->required();
  app.add_option("--file", o.file, "survey file (docs/surveys.md): resumed from at start, one fsync'ed row per station")->required();
  app.add_option("-p,--plugin,--estimator", o.estimator, "estimator whose attitude to read (plumb/attitude/<plugin>)")
      ->capture_default_str();
  app.add_option("--attitude-topic", o.attitude_topic, "attitude topic to read instead of plumb/attitude/<plugin>");
  app.add_option("--estimator-host", o.estimator_host,
                 "the estimator host running the plugin (its plumb-estimator --name; default this computer's host "
                 "name): --error-model auto on the strapdown navigator reads the navigator's parameters it writes");
  app.add_option("--estimator-wait", o.estimator_wait_s,
                 "seconds to wait at start for the estimator host's parameters (then plumb's own terms, said)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  components::add_survey_options(app, o.survey);
  app.add_option("--count", o.count, "exit once the survey holds this many stations (0: run until stopped)");
  app.add_option("--timeout", o.timeout_s, "exit with an error if --count is not reached within this many seconds");
  app.add_option("--linger", o.linger_s, "seconds to stay after --count so that readers get the last station")->capture_default_str();
  app.add_flag("-q,--quiet", o.quiet, "do not print each station");
  app.add_option("--depth-clock-offset", o.depth_clock_offset_s,
                 "seconds the depth's stamps run ahead of the sensors' (negative: behind); given, the offset is not "
                 "estimated (0: the depth is on the sensors' clock, as plumb-sim's)");
  app.add_option("--depth-clock-drift-ppm", o.depth_clock_drift_ppm,
                 "parts per million the depth's clock runs fast (negative: slow); given, nothing is estimated")
      ->check(CLI::Range(-1000.0, 1000.0));
  app.add_option("--sensor-topic", o.sensor_topic,
                 "sensor topic whose stillness the depth's stops are matched with to estimate the depth clock")
      ->capture_default_str();
  components::add_clearance_options(app, o.clearance, /*offsets_required=*/false);
  app.add_option("--offset-error-model", o.offset_error_model,
                 "error model of station-list offset wells: a built-in tool code (MWD, MWD:rev4, GYRO-NS, ...) or a tool "
                 "code file; the survey's reference field and latitude")
      ->capture_default_str();
  if (const int status = components::parse_command_line(app, argc, argv); status >= 0) return status;
  try {
    return survey_component::run_live_survey(o);
  } catch (const std::exception& e) {
    return components::exit_on_error("plumb-survey", e);
  }
}
