// The tool's temperature and its biases: a drilling tool heats by tens of degrees when circulation
// stops and cools when it starts again, and its gyro and accelerometer biases move with it. With
// the datasheet's coefficients (gyro_bias_temp_dph_per_c, accel_bias_temp_mg_per_c) the readings
// are corrected by coefficient x (T - T0), T0 the temperature at the stream's first reading (inside
// the alignment, whose bias estimate is the bias at T0); what the coefficient is not known to
// (bias_temp_sd of it) stays as process noise on the bias states. Without them the readings stay
// as they are and the grade's typical coefficient is the uncertainty, said once in a notice.
//
// The noise: the bias error k' (T - T0) has variance sd_k^2 (T - T0)^2. Each epoch adds
// sd_k^2 |(T - T0)^2 - (T' - T0)^2| for the temperature's change since the last (T' before): never
// less than the error's own variance whatever path T took (a swing that returns adds again, which
// is conservative), and nothing while T holds. T is the readings' mean over a few seconds (the
// sensor's noise and steps would otherwise add at every epoch), taken in steps of 0.1 degC. The
// correction is a subtraction per reading, and only when the reading carries a temperature.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/navigator_common.hpp"
#include "plumb/strapdown/navigator_config.hpp"

namespace plumb::strapdown {

class TemperatureDrift {
 public:
  void reset(const NavigatorConfig& config);
  // Every navigable reading: the correction applied to in.f and in.w (when it carries temperature).
  void correct(InputReading& in, Counters& counters);
  // The epoch's process noise (dt long) with the bias uncertainty the temperature's change since the
  // last epoch brings.
  ProcessNoise widen(const ProcessNoise& base, double dt);
  // What the rows say while the readings carry temperature (empty without): the change since T0.
  std::string row_warning() const;
  std::vector<std::string> take_notices();

 private:
  NavigatorConfig config_;
  std::optional<double> t0_;      // the reference temperature (degC)
  double smooth_ = 0;             // the readings' running mean (degC)
  double last_t_ = 0;             // time of the last reading with temperature
  double accounted_ = 0;          // T - T0 the noise has been added up to (degC)
  double pending_ = 0;            // |change of (T - T0)^2| since the last epoch (degC^2)
  double gyro_k_ = 0, accel_k_ = 0;        // applied (rad/s, m/s^2 per degC)
  double gyro_sd_ = 0, accel_sd_ = 0;      // their uncertainty
  double largest_ = 0;            // largest |T - T0| so far
  bool stated_notice_ = false, unknown_notice_ = false;
  std::vector<std::string> notices_;
};

}  // namespace plumb::strapdown
