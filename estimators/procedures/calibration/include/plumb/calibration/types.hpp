// What every calibration procedure takes and gives: stations, their averages, the parameters with
// their standard deviations, and an outcome that is either complete coefficients or an error.
#pragma once

#include <optional>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/core/calibration_model.hpp"
#include "plumb/core/sample.hpp"

namespace plumb::calibration {

// Raised inside a procedure; the procedure's entry point turns it into Outcome::error, so that a
// failed procedure never yields coefficients.
class CalibrationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where the tool is at a station. "+x" means the x axis points up, so the accelerometers read
// f = +g along x (docs/conventions.md: at rest f = -G). "-z@90" adds the turntable rotation about the
// vertical (0, 90, 180, 270). "any" is an unknown orientation (least-squares and magnetometer).
struct Orientation {
  int axis = -1;          // 0, 1, 2 for x, y, z; -1 unknown
  int sign = 1;           // +1 axis up, -1 axis down
  int rotation_deg = 0;   // turntable rotation about the vertical
  bool known() const { return axis >= 0; }
  // Unit direction of the specific force in the tool frame (only when known()).
  Eigen::Vector3d up() const;
  // "+x", "-y@90", "any".
  std::string label() const;
  // The six-position key without the rotation: 0..5 for +x,-x,+y,-y,+z,-z.
  int face() const { return 2 * axis + (sign > 0 ? 0 : 1); }
};
// Throws CalibrationError on an unknown label.
Orientation parse_orientation(const std::string& text);
std::string face_label(int face);

// One station of the station list: a time window of the recording and where the tool was.
struct Station {
  std::string name;
  double start_s = 0;
  double end_s = 0;
  Orientation orientation;
  std::string run;                       // temperature run (24-position); "" for a single run
  std::vector<double> reference_temps_c; // readings of the reference thermometers (may be empty)
};

// How a station is averaged: readings are block means of block_s; the station is settled when the
// last `repeats` readings agree within the tolerance (k_sigma times the noise of one reading, and
// at least the absolute floors), and the average runs from the end of those readings to the
// station's end.
struct SettleOptions {
  double block_s = 1.0;
  int repeats = 3;
  double k_sigma = 4.0;
  double min_tolerance_accel = 0;   // raw units
  double min_tolerance_mag = 0;
  bool check_mag = false;           // kept for callers; the magnetometers are now always checked (stillness)
};

struct StationAverage {
  Station station;
  Eigen::Vector3d accel = Eigen::Vector3d::Zero();      // raw mean
  Eigen::Vector3d accel_se = Eigen::Vector3d::Zero();   // standard error of the mean
  Eigen::Vector3d mag = Eigen::Vector3d::Zero();
  Eigen::Vector3d mag_se = Eigen::Vector3d::Zero();
  double raw_temp_c = 0;          // thermometer reading (raw)
  double raw_temp_se = 0;
  bool has_temperature = false;
  std::size_t samples_used = 0;
  std::size_t samples_rejected = 0;   // flagged unusable
  double settled_after_s = 0;         // from the station's start
  std::vector<std::string> notes;     // motion seen and left out (the report's warnings)
};

// Averages every station of `samples` (sorted by time). Throws CalibrationError naming the station
// that has too few samples or never settles.
std::vector<StationAverage> average_stations(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                                             const SettleOptions& options = {});
StationAverage average_station(const std::vector<Sample>& samples, const Station& station,
                               const SettleOptions& options = {});

struct Parameter {
  std::string name;     // e.g. "accel.bias.x"
  double value = 0;
  double sd = 0;        // predicted standard deviation
  std::string unit;
};

// Per station: what the calibrated data says against what the station should be.
struct StationResidual {
  std::string station;
  double norm_error = 0;             // |calibrated f| - g, m/s^2 (or |B| - B for the magnetometer)
  double direction_error_deg = -1;   // angle between calibrated f and the nominal up (known only)
  double inclination_before_deg = -1;  // |inclination error| with the nominal (uncalibrated) model
  double inclination_after_deg = -1;
};

// What the calibration's own statistics predict for its error in use, from the fit's covariance
// (scaled up by chi2/dof when the fit's residuals exceed its noise): the largest 3-sigma
// inclination and azimuth error over a grid of orientations and the calibrated temperature range,
// with the parameters that contribute most at the worst point.
struct ErrorPrediction {
  bool valid = false;
  double inclination_deg = 0;        // worst 3-sigma inclination error
  double inclination_at_deg = 0;     // where: inclination, toolface, temperature
  double toolface_at_deg = 0;
  double temperature_at_c = 0;
  double azimuth_deg = 0;            // worst 3-sigma azimuth error (inclinations 10..120 deg)
  double azimuth_at_inclination_deg = 0;
  std::vector<std::pair<std::string, double>> contributions;   // parameter group, its 3-sigma share (deg), largest first
  std::string grid;                  // the orientations and temperatures it covers
};

// What the stations' residuals after calibration are made of: the part the four turntable
// rotations of a face share (what the sensor model leaves) and the part that turns with the
// turntable (table top tilt, misplaced stations), which the rotation averaging cancels.
struct ResidualSplit {
  bool valid = false;
  double sensor_deg = 0;        // largest face-mean direction error
  double orientation_deg = 0;   // largest station deviation from its face mean
  std::string worst_station;    // the station with the largest orientation part
};

struct Result {
  CalibrationModel model;
  ErrorPrediction predicted;
  ResidualSplit split;
  std::vector<std::string> dropped;   // stations the robust fit left out, with why
  std::vector<Parameter> parameters;
  std::vector<StationResidual> residuals;
  std::vector<std::string> warnings;
  double residual_rms = 0;   // of the fit, in the residuals' own units
  std::string summary;       // one paragraph for the report
};

// Either a complete Result or an error; never both, never a half result.
struct Outcome {
  std::optional<Result> result;
  std::string error;
  std::vector<std::string> warnings;   // also those raised before the failure
  bool ok() const { return result.has_value(); }
};

// Looks a parameter up by name; nullptr when absent.
const Parameter* find_parameter(const Result& r, const std::string& name);

}  // namespace plumb::calibration
