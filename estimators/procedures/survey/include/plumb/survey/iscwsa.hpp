// The ISCWSA error model of MWD surveys (Williamson, SPE 67616, 2000; the toolface-independent
// sensor terms of SPE 63275; the revisions 4 and 5 of the ISCWSA MWD model and the OWSG tool codes
// built on them). Each term (an error source) gives, at every station, a change of measured depth,
// inclination and azimuth: its magnitude times a weighting function of the station's attitude and
// the reference field. The change moves the position through the derivatives of the path with
// respect to the station's (MD, I, A) (the balanced-tangential derivatives of SPE 67616 Appendix A,
// as the model defines them); terms propagate as random (independent station to station: their
// covariances add) or systematic, per well or global (common to the stations: their position
// vectors add first). A few terms have their own forms: near vertical (inclination below the
// model's limit) the azimuth-dependent ones take the vertical form of the model, and the long
// course-length terms XCLA and XCLH of revision 5 act on position directly. The gyro model (SPE
// 90408) is the same framework with the gyro's own terms (iscwsa_gyro.hpp): a gyrocompass's at
// each static station, and a continuous run's drift and random walk from its initialisation.
//
// Checked against ISCWSA's example workbooks (tests/data/iscwsa): every term's covariance at each
// diagnostic depth within 0.1 %.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace plumb::survey::iscwsa {

enum class Propagation { Random, Systematic, Global, WellByWell };

struct Term {
  std::string code;             // e.g. "ABXY-TI1S"
  std::string weight_function;  // e.g. "ABXY-TI1": the weighting function the term uses
  double magnitude = 0;         // 1 sigma, in `unit`
  std::string unit;             // m, -, 1/m, m/s2, nT, deg, deg.nT
  Propagation propagation = Propagation::Systematic;
};

// How a gyro tool surveys (the ISCWSA gyro model, SPE 90408): a gyrocompass at each station in
// its static inclination range, and from the first station in its continuous range on, a run of
// the gyros from one initialisation: a gyrocompass (the last static station before the run, or
// the run's first station) whose azimuth error the run keeps, or a known azimuth (the EXT terms).
enum class GyroInitialisation { Gyrocompass, Reference };

struct GyroRunning {
  double static_start_inc_deg = 0, static_end_inc_deg = 180;
  bool continuous = false;
  double continuous_start_inc_deg = 0, continuous_end_inc_deg = 180;
  GyroInitialisation initialisation = GyroInitialisation::Gyrocompass;
  // The inclination at which an initialising gyrocompass is evaluated (the codes' "Initialisation
  // Inc"); NaN: the initialising station's own.
  double initialisation_inc_deg = std::numeric_limits<double>::quiet_NaN();
  // The time of a course: its length over the running speed, or (0) the stations' own times.
  double running_speed_m_per_h = 0;
  // The share of a station's gyro noise left in an initialising gyrocompass, a longer measurement
  // (SPE 90408's examples: 0.5; OWSG GYRO-NS-CT 0.4082).
  double noise_reduction_factor = 1;
  // Where each gyro set's drift and random walk grow: over the part of each course within its
  // inclination range, from the first station on (held beyond); NaN: the run's range. A z gyro
  // cannot see a turn toward horizontal, x-y gyros none toward vertical: SPE 90408's Model #4 runs
  // its z gyro from the surface to 17 deg, then its x-y gyros to 150 deg. A course across the
  // hand-over is shared at its inclination, each set for its own part.
  double z_drift_from_inc_deg = std::numeric_limits<double>::quiet_NaN();
  double z_drift_to_inc_deg = std::numeric_limits<double>::quiet_NaN();
  double xy_drift_from_inc_deg = std::numeric_limits<double>::quiet_NaN();
  double xy_drift_to_inc_deg = std::numeric_limits<double>::quiet_NaN();
};

struct ToolCode {
  std::string name;             // e.g. "MWD rev5"
  int revision = 5;             // 4: revision 4's derivatives; 5 and later: revision 5's
  double tortuosity_rad_per_m = 0.000572615;  // XCL terms (1 deg / 100 ft)
  std::vector<Term> terms;
  double xy_accelerometer_cant_deg = 0;  // the AXY- terms of x-y accelerometers canted to the tool axis
  GyroRunning gyro{};           // read by the gyro terms only
};

// The reference field and the survey's corrections at the well.
struct Field {
  double gravity_mps2 = 9.80665;
  double total_b_nT = 50000;
  double dip_deg = 60;
  double vertical_inc_limit_deg = 1e-4;  // below it a station is "vertical" for the model
  double latitude_deg = std::numeric_limits<double>::quiet_NaN();  // a gyrocompass's terms need it
  // Added to a station's azimuth_deg, its true azimuth: the gyro terms weigh the true azimuth (a
  // gyrocompass reads the earth's rate, which points to true north). A grid survey's convergence
  // (true = grid + convergence), a magnetic one's declination; 0 for a true survey.
  double true_azimuth_offset_deg = 0;
  // Whether the first station is a survey of its own (its errors tilt the half course below it) or
  // a tie-in point whose direction is given (no error of its own). ISCWSA's error-model workbooks
  // tie in; the ISCWSA clearance set (tests/data/iscwsa_clearance) surveys from MD 0 and from a
  // sidetrack's kick-off, and its listings count that station's errors.
  bool first_station_surveyed = false;
};

// One station: measured depth, inclination, the azimuth of the survey's position frame (true or
// grid north) and the magnetic azimuth the sensors measured, its true vertical depth, and its time
// (s; the continuous gyro terms' time when the tool code gives no running speed).
struct Station {
  double md_m = 0, inclination_deg = 0, azimuth_deg = 0, magnetic_azimuth_deg = 0, tvd_m = 0;
  double t_s = std::numeric_limits<double>::quiet_NaN();
};

struct Result {
  std::vector<std::string> codes;                      // one per term
  std::vector<std::vector<Eigen::Matrix3d>> per_term;  // [term][station], north/east/down, m^2
  std::vector<Eigen::Matrix3d> random;                 // the random terms, per station
  std::vector<Eigen::Matrix3d> total;                  // every term, per station
  // The variance of each station's own inclination and azimuth (rad^2) from every term, and from the
  // random ones: what the model says a station's angles are worth.
  std::vector<Eigen::Vector2d> angle_variance, random_angle_variance;
};

// Measured depths must increase strictly (std::invalid_argument otherwise); an unknown weighting
// function is std::invalid_argument naming the term.
Result propagate(const std::vector<Station>& stations, const ToolCode& tool, const Field& field);

// One leg of a survey program: the stations from this measured depth on (to the next leg's) were
// surveyed by this tool. The first leg also holds every station above its depth.
struct Leg {
  double from_md_m = -std::numeric_limits<double>::infinity();
  ToolCode tool;
};

// A well surveyed in legs, each by its own tool (a gyro in the top hole, MWD below; a navigator
// re-tuned while drilling). Each leg's systematic terms are its own draw, so a leg's errors move
// the stations below it rigidly; a per-well (W) or global (G) term of the same code is one draw
// across the legs; a gyro leg runs from its own first station. Per-term codes are "TOOL: CODE"
// (the leg's tool name, or "leg N") when there is more than one leg. Leg depths must increase
// strictly (std::invalid_argument otherwise).
Result propagate(const std::vector<Station>& stations, const std::vector<Leg>& legs, const Field& field);

// Places `leg` among a program's legs (sorted by depth): one that starts at the same depth is
// replaced, those deeper stay.
void insert_leg(std::vector<Leg>& legs, Leg leg);

// A tool code file is read by plumb/survey/tool_code_file.hpp (estimators/formats/survey_file).

// The built-in tool codes: "MWD" (ISCWSA MWD revision 5, OWSG values of 5.1.1: DEC-OH 0.21 deg),
// "MWD:rev5" (the revision 5 example workbooks' values: DEC-OH 0.20 deg), "MWD:rev4", "MWD+IFR1"
// (OWSG A005Mc, revision 5.1); the gyro codes "GYRO-NS", "GYRO-NS-CT", "GYRO-MWD" (OWSG set A,
// revision 5.1) and "GYRO:tactical", "GYRO:mems" (a strapdown tool of plumb's IMU grades run
// continuously from a known azimuth). Throws std::invalid_argument listing the names for another.
ToolCode builtin_tool_code(const std::string& name);
std::vector<std::string> builtin_tool_codes();

// The weighting functions this model knows.
bool known_weight_function(const std::string& name);

// The unit a weighting function's magnitude is given in (Term::unit of the built-in codes): m, 1/m,
// -, m/s2, nT, deg, deg.nT, deg/hr or deg/sqrt(hr); empty for an unknown weighting function.
std::string model_unit(const std::string& weight_function);
// A magnitude given in `unit` in model_unit(weight_function): ft -> m, 1/ft -> 1/m, ppm and % -> -,
// mg and ug -> m/s2, uT -> nT, rad and mrad -> deg, deg/h -> deg/hr, deg/sqr(hr) (the OWSG codes'
// spelling) -> deg/sqrt(hr). std::invalid_argument naming the units it accepts for another unit
// (a unit of another quantity, or one it does not know).
double to_model_unit(const std::string& weight_function, double magnitude, const std::string& unit);

// Whether the tool code gyrocompasses (its terms need Field::latitude_deg).
bool needs_latitude(const ToolCode& tool);
// Whether the tool code has a gyro's terms (the ISCWSA gyro model, SPE 90408).
bool has_gyro_terms(const ToolCode& tool);

}  // namespace plumb::survey::iscwsa
