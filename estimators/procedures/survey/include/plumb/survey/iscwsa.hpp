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
// course-length terms XCLA and XCLH of revision 5 act on position directly.
//
// Checked against ISCWSA's example workbooks (tests/data/iscwsa): every term's covariance at each
// diagnostic depth within 0.1 %.
#pragma once

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

struct ToolCode {
  std::string name;             // e.g. "MWD rev5"
  int revision = 5;             // 4: revision 4's derivatives; 5 and later: revision 5's
  double tortuosity_rad_per_m = 0.000572615;  // XCL terms (1 deg / 100 ft)
  std::vector<Term> terms;
};

// The reference field and the survey's corrections at the well.
struct Field {
  double gravity_mps2 = 9.80665;
  double total_b_nT = 50000;
  double dip_deg = 60;
  double vertical_inc_limit_deg = 1e-4;  // below it a station is "vertical" for the model
};

// One station: measured depth, inclination, the azimuth of the survey's position frame (true or
// grid north) and the magnetic azimuth the sensors measured, and its true vertical depth.
struct Station {
  double md_m = 0, inclination_deg = 0, azimuth_deg = 0, magnetic_azimuth_deg = 0, tvd_m = 0;
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

// A tool code file is read by plumb/survey/tool_code_file.hpp (estimators/formats/survey_file).

// The built-in tool codes: "MWD" (ISCWSA MWD revision 5, OWSG values of 5.1.1: DEC-OH 0.21 deg),
// "MWD:rev5" (the revision 5 example workbooks' values: DEC-OH 0.20 deg), "MWD:rev4", "MWD+IFR1"
// (OWSG A005Mc, revision 5.1). Throws std::invalid_argument listing the names for another.
ToolCode builtin_tool_code(const std::string& name);
std::vector<std::string> builtin_tool_codes();

// The weighting functions this model knows.
bool known_weight_function(const std::string& name);

}  // namespace plumb::survey::iscwsa
