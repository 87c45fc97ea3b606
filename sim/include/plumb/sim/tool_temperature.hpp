// The drilling tool's temperature through a run (off by default): mud circulating while the string
// drills carries the tool's heat away toward the mud's temperature; when circulation stops (a pipe
// connection, a survey stop) the still mud around the tool warms toward the formation's. Each is a
// first-order lag, evaluated in closed form phase by phase of the plan. The IMU's biases follow the
// true temperature by the run's coefficients (ImuModel); the sensor reads it with its own noise and
// quantization (Sample::temp_c, flags::kHasTemperature).
//
// Default figures and why: a swing of 30 degC between circulating mud and the still mud's
// equilibrium (a few thousand metres down, the mud returns tens of degrees below the static
// formation temperature); heating at a stop with a 120 s time constant (natural convection in the
// still annulus: a downhole tool's temperature rises tens of degrees within minutes of the pumps
// stopping); cooling at 90 s (forced convection by the flowing mud is faster than still-mud heating);
// the sensor 0.05 degC rms with 1/16 degC steps (a digital temperature sensor's 12-bit reading).
#pragma once

#include <cstdint>
#include <vector>

namespace plumb::sim {

struct ToolTemperature {
  bool enabled = false;        // off: no temperature on the samples, biases constant (as before)
  double circulating_c = 60;   // what the tool tends to while mud circulates (drilling)
  double formation_c = 90;     // what it tends to while circulation stops (the run's stops and alignment)
  double start_c = 60;         // at the start of the run (the string circulated before it)
  double heat_tau_s = 120;     // first-order time constant toward formation_c at a stop
  double cool_tau_s = 90;      // ... toward circulating_c while drilling
  double sensor_sigma_c = 0.05;
  double sensor_quantum_c = 0.0625;  // 0: none
};

// The true temperature at any t of a plan whose phases (start times, circulating or not) are given.
class TemperatureHistory {
 public:
  TemperatureHistory() = default;
  // starts[i], circulating[i]: phase i begins at starts[i] (starts[0] = 0, increasing).
  TemperatureHistory(const ToolTemperature& model, std::vector<double> starts, std::vector<bool> circulating);
  double at(double t) const;  // degC; before 0 the start's, past the last start its phase goes on

 private:
  ToolTemperature model_;
  std::vector<double> starts_, start_temp_;
  std::vector<bool> circulating_;
};

}  // namespace plumb::sim
