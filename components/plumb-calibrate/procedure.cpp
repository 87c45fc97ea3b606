#include "procedure.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <thread>

#include "plumb/components/calibration_convert.hpp"
#include "plumb/calibration/report.hpp"
#include "plumb/transport/topic_names.hpp"

namespace plumb::calibrate {

namespace {

CalibrationModel load_or_default(const std::string& path) {
  return path.empty() ? CalibrationModel{} : read_calibration_file(path);
}

std::string default_id(const Options& o) {
  if (!o.calibration_id.empty()) return o.calibration_id;
  char buf[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(buf, sizeof buf, "%Y%m%dT%H%M%SZ", std::gmtime(&now));
  return o.procedure + "-" + buf;
}

}  // namespace

calibration::Outcome run_procedure(const Options& o, const std::vector<Sample>& samples,
                                   const std::vector<calibration::Station>& stations) {
  using namespace calibration;
  CommonOptions common;
  common.g = o.g;
  common.base = load_or_default(o.base);
  common.nominal = load_or_default(o.nominal);
  common.tool_id = o.tool_id;
  common.calibration_id = default_id(o);
  common.stamp_s = static_cast<double>(std::time(nullptr));
  const Procedure p = parse_procedure(o.procedure);
  common.settle = default_settle(p);
  switch (p) {
    case Procedure::SixPosition:
      return six_position(samples, stations, common);
    case Procedure::TwentyFourPosition: {
      TwentyFourOptions t;
      static_cast<CommonOptions&>(t) = common;
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
    write_calibration(out, r.model);
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
  auto connection = components::connect(o.transport, "plumb-calibrate");
  auto writer = transport::make_writer<topics::CalibrationCoefficients>(
      *connection.participant, transport::topic_names::kCalibration, transport::Qos::calibration());
  writer.write(components::to_topic(model));
  std::printf("published coefficients '%s' on %s; staying %.0f s for late joiners\n", model.calibration_id.c_str(),
              transport::topic_names::kCalibration, o.linger_s);
  std::fflush(stdout);
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(o.linger_s);
  while (!components::g_stop && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
}

}  // namespace plumb::calibrate
