#include "procedure.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <thread>

#include "plumb/calibration/report.hpp"
#include "plumb/components/calibration_convert.hpp"
#include "plumb/csv/coefficients_file.hpp"
#include "plumb/transport/topic_names.hpp"

namespace plumb::calibrate_component {

namespace {

CalibrationModel load_or_default(const std::string& path) {
  return path.empty() ? CalibrationModel{} : csv::read_calibration_file(path);
}

std::string default_id(const Options& o) {
  if (!o.calibration_id.empty()) return o.calibration_id;
  char buf[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(buf, sizeof buf, "%Y%m%dT%H%M%SZ", std::gmtime(&now));
  return o.procedure + "-" + buf;
}

calibration::Outcome run_chosen_procedure(const Options& o, const std::vector<Sample>& samples,
                                          const std::vector<calibration::Station>& stations) {
  using namespace calibration;
  CommonOptions common;
  common.g = o.g;
  common.base = load_or_default(o.base);
  common.nominal = load_or_default(o.nominal);
  common.tool_id = o.tool_id;
  common.calibration_id = default_id(o);
  common.stamp_s = static_cast<double>(std::time(nullptr));
  common.max_error_deg = o.max_error_deg;
  const Procedure p = parse_procedure(o.procedure);
  common.settle = default_settle(p);
  switch (p) {
    case Procedure::SixPosition:
      return six_position(samples, stations, common);
    case Procedure::TwentyFourPosition: {
      TwentyFourOptions t;
      static_cast<CommonOptions&>(t) = common;
      t.temperature_order = o.temperature_order;
      return twenty_four_position(samples, stations, t);
    }
    case Procedure::LeastSquares: {
      LeastSquaresOptions l;
      static_cast<CommonOptions&>(l) = common;
      return least_squares(samples, stations, l);
    }
    case Procedure::Magnetometer: {
      MagnetometerOptions m;
      static_cast<CommonOptions&>(m) = common;
      m.total_field_ut = o.total_field_ut;
      m.calibrate_accelerometers = o.with_accelerometers;
      return magnetometer(samples, stations, m);
    }
  }
  return {};
}

}  // namespace

calibration::Outcome run_procedure(const Options& o, const std::vector<Sample>& samples,
                                   const std::vector<calibration::Station>& stations) {
  calibration::Outcome outcome = run_chosen_procedure(o, samples, stations);
  // The units of the package the coefficients are made for travel with them (docs/calibration.md
  // 2.1); the typical simulated package sends volts and magnetometer counts (one made from
  // --sim-truth sends whatever that file's coefficients expect: not stated).
  const bool typical_sim = o.simulate_turntable && o.sim_truth.empty();
  if (outcome.result) {
    outcome.result->model.accel_units = !o.accel_units.empty() ? o.accel_units : typical_sim ? "V" : "";
    outcome.result->model.mag_units = !o.mag_units.empty() ? o.mag_units : typical_sim ? "counts" : "";
  }
  return outcome;
}

int write_outputs(const Options& o, const calibration::Outcome& outcome) {
  const std::string report = calibration::format_report(outcome, o.procedure);
  if (!o.report.empty()) {
    std::ofstream out(o.report);
    if (!(out << report)) std::fprintf(stderr, "plumb-calibrate: cannot write report %s\n", o.report.c_str());
  }
  for (const auto& w : outcome.warnings) std::fprintf(stderr, "plumb-calibrate: warning: %s\n", w.c_str());
  if (!outcome.ok()) {
    std::fprintf(stderr, "plumb-calibrate: calibration failed: %s (no coefficients written or published)\n",
                 outcome.error.c_str());
    return 1;
  }
  const auto& r = *outcome.result;
  if (!o.output.empty()) {
    std::ofstream out(o.output);
    csv::write_calibration(out, r.model);
    if (!out) {
      std::fprintf(stderr, "plumb-calibrate: cannot write %s\n", o.output.c_str());
      return 1;
    }
  }
  double before = -1, after = -1;
  calibration::inclination_summary(r, before, after);
  std::printf("%s\n", r.summary.c_str());
  if (after >= 0) std::printf("inclination error at the stations: before %.4f deg, after %.5f deg\n", before, after);
  if (!o.output.empty()) std::printf("coefficients written to %s\n", o.output.c_str());
  std::fflush(stdout);
  return 0;
}

void publish_coefficients(const Options& o, const CalibrationModel& model) {
  // The topic carries the version-1 terms only: publishing version-2 coefficients would drop the
  // sensors' temperature terms without a word.
  if (model.format_version() > 1)
    throw std::runtime_error("coefficients with version-2 temperature terms cannot be published on " +
                             std::string(transport::topic_names::kCalibration) +
                             " (the topic carries version 1); give the bridge the file (--calibration)");
  auto connection = components::connect(o.transport, "plumb-calibrate");
  auto writer = transport::make_writer<topics::CalibrationCoefficients>(
      *connection.participant, transport::topic_names::kCalibration, transport::Qos::calibration());
  writer.write(components::to_topic(model));
  std::printf("published coefficients '%s' on %s; staying %.0f s for late joiners\n", model.calibration_id.c_str(),
              transport::topic_names::kCalibration, o.linger_s);
  std::fflush(stdout);
  components::sleep_while_running(o.linger_s);
}

}  // namespace plumb::calibrate_component
