// plumb-calibrate offline: a recorded sensor CSV and a station list in, coefficients and report out.
#pragma once

#include <vector>

#include "options.hpp"
#include "plumb/sim/turntable.hpp"

namespace plumb::calibrate_component {

int run_offline(const Options& o);
// Writes a simulated turntable recording for the procedure: <prefix>sensor.csv,
// <prefix>stations.csv, and the package's true and nominal coefficients <prefix>truth.txt,
// <prefix>nominal.txt.
int write_simulation(const Options& o);
// The simulated sensor package: typical errors from --sim-seed, or the truth of --sim-truth
// (raw units then physical units, nominal conversion the identity).
sim::SensorPackage simulated_package(const Options& o);
// The station plans a procedure asks for (also the simulated operator's moves).
std::vector<sim::StationPlan> plans_for(const Options& o);

}  // namespace plumb::calibrate_component
