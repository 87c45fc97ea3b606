// plumb survey: the survey offline. From a sensor CSV (through an estimator, stations at the stops
// the measured depth shows, or a pipe tally), from an attitude CSV and a depth log, or from a
// station list, to the survey CSV (docs/surveys.md) and a plan and section drawn by plumb-plot.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include "plumb/components/cli.hpp"
#include "plumb/components/survey_options.hpp"
#include "plumb/csv/files.hpp"
#include "plumb/estimator/loader.hpp"
#include "plumb/survey/detector_report.hpp"
#include "plumb/survey/multi_station.hpp"
#include "plumb/survey/survey_file.hpp"
#include "plumb/survey/survey_inputs.hpp"
#include "plots/plot_runner.hpp"
#include "verbs.hpp"

namespace plumb::cli {
namespace {

struct SurveyCommandOptions {
  std::string sensor, attitude, depth, stations;
  std::string estimator = "compensated";
  double window_s = 5;
  std::vector<std::string> params;
  std::string output, plot;
  components::SurveyCliOptions survey;
};

// Stations found in the input go into the survey; a station the survey refuses (depth backwards,
// a duplicate) stops the command with that station named: an offline survey is redone, not patched.
struct Collector {
  survey::Survey& survey;
  double depth_sd_m;
  void operator()(survey::Station s) const {
    if (depth_sd_m >= 0) s.md_sd_m = depth_sd_m;
    survey.add(s);
  }
};

// The navigator's parameters as its host's `plumb param dump` gives them: every one it declares,
// with the value given (--param) or its default.
survey::iscwsa::NavigatorParameters parameters_in_use(const estimator::Runner& runner) {
  survey::iscwsa::NavigatorParameters in_use;
  const estimator::Runner::Slot& slot = runner.slots().front();
  const std::vector<estimator::Info> infos = runner.infos();
  for (const auto& spec : infos.front().parameters) {
    const auto given = slot.parameters.find(spec.name);
    in_use[spec.name] = given != slot.parameters.end() ? given->second : spec.default_value;
  }
  return in_use;
}

void from_sensor_csv(const SurveyCommandOptions& o, estimator::Runner& runner, survey::StationDetector& detector) {
  std::ifstream in(o.sensor);
  if (!in) throw std::runtime_error("cannot open input '" + o.sensor + "'");
  csv::SensorReader reader(in, o.sensor);
  if (!reader.has_depth() && !o.survey.pipe_length_m && o.survey.tally_file.empty())
    throw std::invalid_argument(o.sensor + " has no depth_m column: give --pipe-length or --tally (a pipe tally) instead");
  for (const auto& name : runner.needing_gyro())
    if (!reader.has_gyro()) throw std::invalid_argument("estimator '" + name + "' needs gyros, and " + o.sensor + " has none");
  const auto take = [&](const estimator::Runner::Slot&, Estimate& e) { detector.add_attitude(e, ""); };
  std::vector<Sample> chunk;
  Sample s;
  // A rig's report is a depth that differs from the row before, or the first after rows without
  // one (a report held on every row counts once; an empty cell between reports is no report); a
  // standing, quantized depth that repeats is said again once a second so that windows see it.
  double last_depth_t = -1e300, last_depth = std::numeric_limits<double>::quiet_NaN();
  bool row_had_depth = false;
  const auto push = [&] {
    runner.push(chunk, take);
    chunk.clear();
  };
  while (reader.next(s)) {
    // The depth goes in before the samples: a window is decided once the depth after it is known.
    const bool has_depth = (s.flags & flags::kHasDepth) != 0;
    if (has_depth && (!row_had_depth || s.depth_m != last_depth || s.t - last_depth_t >= 1.0)) {
      detector.add_depth({s.t, s.depth_m, 0, false});
      last_depth_t = s.t;
      last_depth = s.depth_m;
    }
    row_had_depth = has_depth;
    chunk.push_back(s);
    if (chunk.size() == 1024) push();
  }
  push();
  runner.flush(take);
}

int run_survey(const SurveyCommandOptions& o) {
  const int inputs = !o.sensor.empty() + !o.attitude.empty() + !o.stations.empty();
  if (inputs != 1) throw std::invalid_argument("give exactly one of --input (sensor CSV), --attitude, --stations");
  if (!o.attitude.empty() && o.depth.empty() && !o.survey.pipe_length_m && o.survey.tally_file.empty())
    throw std::invalid_argument("--attitude needs --depth (a depth log), or --pipe-length or --tally (a pipe tally)");
  std::optional<estimator::Runner> runner;
  std::optional<survey::iscwsa::NavigatorParameters> navigator;
  if (!o.sensor.empty()) {
    runner = estimator::load_runner({o.estimator});
    runner->configure(o.params, o.window_s);
    if (o.estimator == components::kNavigatorPlugin) navigator = parameters_in_use(*runner);
  }
  survey::Survey result(components::make_survey_options(o.survey, o.sensor.empty() ? "" : o.estimator,
                                                        navigator ? &*navigator : nullptr));
  const Collector collect{result, o.survey.depth_sd_m};
  std::vector<std::string> notes;
  survey::StationDetector detector(components::make_detector_options(o.survey), collect,
                                   [&](const std::string& n) { notes.push_back(n); });
  const std::string input = !o.stations.empty() ? o.stations : !o.attitude.empty() ? o.attitude : o.sensor;
  try {
    if (!o.stations.empty()) {
      for (const auto& s : survey::read_station_csv(o.stations)) collect(s);
    } else if (!o.attitude.empty()) {
      const auto estimates = survey::read_attitude_csv(o.attitude, o.window_s);
      if (!o.depth.empty())
        for (const auto& d : survey::read_depth_csv(o.depth)) detector.add_depth(d);
      for (const auto& e : estimates) detector.add_attitude(e, "");
      detector.flush();
    } else {
      from_sensor_csv(o, *runner, detector);
      detector.flush();
    }
  } catch (const survey::StationError& e) {
    // The input is wrong, not the command line: a runtime error (exit 1) naming the input.
    throw std::runtime_error(input + ": " + e.what());
  }

  const std::string text = survey::survey_text(result);
  if (o.output.empty()) std::cout << text;
  else survey::write_file_atomically(o.output, text);
  for (const auto& n : notes) std::cerr << "plumb survey: " << n << '\n';
  const auto& c = detector.counters();
  if (!result.options().later_legs.empty())
    std::cerr << "plumb survey: error model " << survey::error_model_text(result.options()) << '\n';
  std::cerr << "plumb survey: " << result.rows().size() << " station(s), " << result.failed_qc() << " failed QC";
  if (o.stations.empty()) std::cerr << " (" << survey::describe_windows(c) << ")";
  std::cerr << '\n';
  if (o.stations.empty() && std::isfinite(detector.depth_sd_m()) && (!o.depth.empty() || !o.sensor.empty()))
    std::cerr << "plumb survey: depth sigma " << detector.depth_sd_m() << " m ("
              << (o.survey.depth_sd_m >= 0 ? "stated" : "measured") << "), still tolerance " << detector.still_tolerance_m()
              << " m\n";
  if (result.rows().empty())
    throw std::runtime_error(o.stations.empty() ? survey::no_station_advice(c, o.estimator, detector.still_tolerance_m())
                                                : "no station found in the input");
  if (!o.plot.empty()) {
    // The plot is drawn from the survey file; without -o, from a copy beside the plot.
    std::string csv = o.output;
    if (csv.empty()) {
      csv = o.plot + ".survey.csv";
      survey::write_file_atomically(csv, text);
    }
    run_plot("survey", csv, o.plot);
    if (o.output.empty()) std::filesystem::remove(csv);
  }
  // Multi-station analysis: reported, not applied (the survey keeps what was measured).
  std::vector<survey::Station> measured;
  for (const auto& row : result.rows()) measured.push_back(row.station);
  const auto msa = survey::estimate_axial_bias(measured, result.options().field);
  if (msa.valid && msa.stations >= 2)
    std::cerr << "plumb survey: multi-station analysis: axial magnetometer bias " << msa.bias_uT << " +- " << msa.sd_uT
              << " uT over " << msa.stations << " stations (|B| residual RMS " << msa.rms_b_before_uT << " -> "
              << msa.rms_b_after_uT << " uT, dip " << msa.rms_dip_before_deg << " -> " << msa.rms_dip_after_deg
              << " deg once removed)\n";
  return 0;
}

}  // namespace

void add_survey_verb(CLI::App& app, Verbs& verbs) {
  auto o = std::make_shared<SurveyCommandOptions>();
  auto* cmd = app.add_subcommand("survey", "Survey offline: stations at the stops, QC, minimum curvature, uncertainty; "
                                           "survey CSV and plot (docs/surveys.md)");
  cmd->add_option("-i,--input", o->sensor, "sensor CSV with depth_m (or with --pipe-length), run through --estimator");
  cmd->add_option("--attitude", o->attitude, "attitude CSV (docs/conventions.md), with --depth or --pipe-length");
  cmd->add_option("--depth", o->depth, "depth log CSV: t,depth_m[,depth_sd_m] on the attitude's clock");
  cmd->add_option("--stations", o->stations, "station list CSV: md_m,inclination_deg,azimuth_deg (magnetic) and "
                                             "optional sigmas and measured field");
  cmd->add_option("-e,--estimator,--plugin", o->estimator, "estimator plugin for --input")->capture_default_str();
  cmd->add_option("-w,--window", o->window_s, "estimator window, s (--input); attitude window length (--attitude; "
                                              "0: the rows' spacing)")
      ->capture_default_str();
  components::add_param_option(*cmd, o->params);
  cmd->add_option("-o,--output", o->output, "survey CSV to write (default: standard output); written whole or not at all");
  cmd->add_option("--plot", o->plot, "plan view and vertical section to draw (with plumb-plot and python3-matplotlib): "
                                     "FILE.png, .svg or .pdf");
  components::add_survey_options(*cmd, o->survey);
  verbs.add(cmd, [o] { return run_survey(*o); });
}

}  // namespace plumb::cli
