#include "offline.hpp"

#include <cstdio>
#include <fstream>

#include "plumb/calibration/procedures.hpp"
#include "plumb/calibration/station_list.hpp"
#include "plumb/csv/coefficients_file.hpp"
#include "plumb/csv/files.hpp"
#include "procedure.hpp"

namespace plumb::calibrate_component {

int run_offline(const Options& o) {
  if (o.input.empty() || o.stations.empty())
    throw std::runtime_error("offline calibration needs --input sensor.csv and --stations stations.csv (or --live)");
  calibration::parse_procedure(o.procedure);  // a wrong name fails before reading anything
  std::vector<Sample> samples;
  std::vector<calibration::Station> stations;
  try {
    samples = csv::read_sensor_file(o.input);
    stations = calibration::read_station_list(o.stations);
  } catch (const std::exception& e) {
    // The report is written whatever happens (docs/calibration.md): it says why there are no
    // coefficients.
    calibration::Outcome failed;
    failed.error = e.what();
    return write_outputs(o, failed);
  }
  std::printf("%s: %zu samples, %zu stations, procedure %s\n", o.input.c_str(), samples.size(), stations.size(),
              o.procedure.c_str());
  const auto outcome = run_procedure(o, samples, stations);
  const int code = write_outputs(o, outcome);
  if (code == 0 && o.publish) publish_coefficients(o, outcome.result->model);
  return code;
}

std::vector<sim::StationPlan> plans_for(const Options& o) {
  switch (calibration::parse_procedure(o.procedure)) {
    case calibration::Procedure::SixPosition:
      return sim::six_position_plan(60);
    case calibration::Procedure::TwentyFourPosition:
      return sim::twenty_four_position_plan({25, 75, 125, 175, 200, 225}, 40);
    case calibration::Procedure::LeastSquares:
    case calibration::Procedure::Magnetometer:
      return sim::random_static_plan(o.positions, o.sim_seed + 1, 30);
  }
  return {};
}

sim::SensorPackage simulated_package(const Options& o) {
  auto pkg = sim::SensorPackage::typical(sim::AccelOutput::Voltage, o.sim_seed);
  if (!o.sim_truth.empty()) {
    pkg.truth = csv::read_calibration_file(o.sim_truth);
    pkg.nominal = CalibrationModel{};
  }
  return pkg;
}

int write_simulation(const Options& o) {
  auto pkg = simulated_package(o);
  const auto proc = calibration::parse_procedure(o.procedure);
  if (proc == calibration::Procedure::LeastSquares && o.sim_truth.empty()) pkg.truth.accelerometer.second_order.setZero();
  sim::Rig rig;
  rig.seed = o.sim_seed;
  rig.g = o.g;
  rig.total_b = o.total_field_ut;
  const auto rec = sim::record(pkg, rig, plans_for(o));
  const std::string prefix = o.write_simulation;
  {
    std::ofstream out(prefix + "sensor.csv");
    out << "# plumb-calibrate --write-simulation: raw outputs of a simulated sensor package (volts, counts)\n";
    csv::write_sensor_header(out, false, true);
    for (const auto& s : rec.samples) csv::write_sensor_row(out, s, false, true);
    if (!out) throw std::runtime_error("cannot write " + prefix + "sensor.csv");
  }
  std::vector<calibration::Station> stations;
  for (const auto& s : rec.stations) {
    calibration::Station st;
    st.name = s.plan.name;
    st.start_s = s.start_s;
    st.end_s = s.end_s;
    st.orientation = calibration::parse_orientation(s.plan.orientation);
    st.run = s.plan.run;
    st.reference_temps_c = s.reference_temps_c;
    stations.push_back(st);
  }
  {
    std::ofstream out(prefix + "stations.csv");
    calibration::write_station_list(out, stations);
  }
  {
    std::ofstream out(prefix + "truth.txt");
    csv::write_calibration(out, pkg.truth);
  }
  {
    std::ofstream out(prefix + "nominal.txt");
    csv::write_calibration(out, pkg.nominal);
  }
  std::printf("wrote %ssensor.csv (%zu samples), %sstations.csv (%zu stations), %struth.txt, %snominal.txt\n",
              prefix.c_str(), rec.samples.size(), prefix.c_str(), stations.size(), prefix.c_str(), prefix.c_str());
  return 0;
}

}  // namespace plumb::calibrate_component
