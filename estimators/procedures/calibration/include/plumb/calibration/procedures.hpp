// The calibration procedures (docs/calibration.md). Each takes the raw recording (samples in the
// raw units of the sensor package: volts, pulses per second, counts) and the station list, and
// returns an Outcome: complete coefficients with standard deviations and residuals, or an error
// naming the station at fault. None of them throws.
#pragma once

#include <vector>

#include "plumb/calibration/types.hpp"
#include "plumb/core/calibration_model.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::calibration {

struct CommonOptions {
  double g = 9.80665;              // local gravity, m/s^2 (the reference of every accelerometer procedure)
  SettleOptions settle;
  // The coefficients a procedure does not determine come from here (e.g. the magnetometer triad of
  // an accelerometer procedure, the accelerometer triad of the magnetometer procedure).
  CalibrationModel base;
  // What "uncalibrated" means in the report's before/after inclination: the nominal (datasheet)
  // conversion of raw units. Default: raw units taken as physical units.
  CalibrationModel nominal;
  std::string tool_id;
  std::string calibration_id;
  double stamp_s = 0;
  // Stations whose raw reading points further than this from their nominal orientation are an
  // error (the tool was placed wrongly).
  double max_orientation_error_deg = 10;
  // After calibration, a station further than this from its nominal orientation gives a warning
  // (turntable tilt and fixture errors stay below it).
  double warn_direction_error_deg = 0.5;
  // A procedure never yields coefficients whose own predicted (3-sigma) inclination error over all
  // orientations and the calibrated temperature range exceeds this (plumb-calibrate --max-error-deg).
  double max_error_deg = 0.005;
};

// docs/methods.md section 3: six stations, each axis at +g and -g with the others horizontal.
Outcome six_position(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                     const CommonOptions& options = {});
Outcome six_position(const std::vector<StationAverage>& averages, const CommonOptions& options = {});

struct TwentyFourOptions : CommonOptions {
  double reference_temp_c = 25;      // T0 of the temperature terms
  double max_run_temp_spread_c = 3;  // a station this far from its run's temperature: warning
  double nonlinear_above_c = 175;    // the thermometer gets a cubic when the runs go above this
  // Order of the polynomial in temperature of each sensor's bias and scale drift (1..3); 0 chooses
  // it from the residuals (docs/calibration.md 4.3).
  int temperature_order = 0;
};

// docs/methods.md section 2: per temperature run, 24 stations (each axis up and down, four rotations about the
// vertical); thermometer correction from the reference thermometers; temperature coefficients from
// the runs at several temperatures.
Outcome twenty_four_position(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                             const TwentyFourOptions& options = {});
Outcome twenty_four_position(const std::vector<StationAverage>& averages, const TwentyFourOptions& options = {});

struct LeastSquaresOptions : CommonOptions {
  int min_stations = 12;
};

// Any number of static positions in unknown orientations: |S (u - bias)| = g at every station,
// S lower triangular (the tool frame's x axis is the x accelerometer's, y in the plane of the x and
// y accelerometers). 9 parameters, Levenberg-Marquardt, standard deviations from the Jacobian and
// the residual variance.
Outcome least_squares(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                      const LeastSquaresOptions& options = {});
Outcome least_squares(const std::vector<StationAverage>& averages, const LeastSquaresOptions& options = {});

struct MagnetometerOptions : CommonOptions {
  double total_field_ut = 48.4;   // local |B|, microtesla
  int min_stations = 12;
  // If true, the accelerometers are first calibrated by least_squares on the same stations;
  // otherwise options.base's accelerometer triad gives the gravity of each station.
  bool calibrate_accelerometers = false;
};

// Hard iron (bias) and soft iron (full 3x3 S) from static positions in a rotation sequence:
// |B| constant and the dip G.B / (|G||B|) constant, which fixes the magnetometer frame to the
// accelerometers'. 13 parameters (bias 3, S 9, sin dip 1).
Outcome magnetometer(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                     const MagnetometerOptions& options = {});
Outcome magnetometer(const std::vector<StationAverage>& averages, const MagnetometerOptions& options = {});

enum class Procedure { SixPosition, TwentyFourPosition, LeastSquares, Magnetometer };
// "6pos", "24pos", "lsq", "mag"; throws CalibrationError listing them on anything else.
Procedure parse_procedure(const std::string& name);
const char* procedure_name(Procedure p);
// Settling options a procedure needs (the magnetometer procedure also waits for the field).
SettleOptions default_settle(Procedure p);

}  // namespace plumb::calibration
