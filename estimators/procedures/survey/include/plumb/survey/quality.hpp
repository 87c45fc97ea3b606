// Quality control of one survey station against the reference field: the measured total gravity
// |G|, total field |B| and dip against the local values (from parameters or a reference file),
// each within a tolerance. A station that fails is kept and flagged with the reason, never dropped.
//
// Default tolerances (the fixed acceptance criteria used for MWD surveys):
//   |B|  +-0.300 uT (300 nT) and dip +-0.25 deg: ISCWSA e-book "Introduction to Wellbore Positioning"
//        (Jamieson), section 22.1 "Checking raw data": a field within 300 nT of the expected one and a
//        dip within 0.25 deg are "within acceptable tolerances";
//   |G|  +-0.003 g (0.0294 m/s^2): the value most operators' survey QC sheets use; the e-book section
//        above gives none for gravity, so this one is plumb's choice, not a cited figure.
// A tool whose own noise or calibration is worse gets its own tolerances (per-tool overrides).
#pragma once

#include <istream>
#include <optional>
#include <string>

namespace plumb::survey {

inline constexpr double kStandardGravity = 9.80665;  // m/s^2 per g

struct ReferenceField {
  std::optional<double> gravity_mps2;  // local gravity
  std::optional<double> total_b_uT;    // total field
  std::optional<double> dip_deg;       // positive downward
  std::optional<double> declination_deg;  // a reference file may carry it too
};

// A reference file: lines `KEY VALUE` (gravity_mps2, total_b_uT, dip_deg, declination_deg), '#'
// comments; the output of a geomagnetic model for the site. Throws std::runtime_error naming
// file and line for anything else.
ReferenceField read_reference_file(std::istream& in, const std::string& source);

struct QcTolerances {
  double gravity_mps2 = 0.003 * kStandardGravity;
  double total_b_uT = 0.300;
  double dip_deg = 0.25;
};

// One station's residuals (measured - reference) and verdict.
struct QcResult {
  bool pass = true;
  double gravity_residual_mps2 = 0;  // 0 when not checked
  double total_b_residual_uT = 0;
  double dip_residual_deg = 0;
  bool gravity_checked = false, total_b_checked = false, dip_checked = false;
  std::string reason;  // every failed check, "; "-separated; empty when it passed
};

// Measured values that are missing (not finite or <= 0 for totals) are not checked and named in
// `reason` ("no |B| measured"), which fails the station: a check that cannot run is not a pass.
// A reference value that is missing fails the station with "no reference |B|" unless the survey
// was told to skip that check (check_* false).
struct QcChecks {
  bool gravity = true, total_b = true, dip = true;
};
QcResult check_station(double total_g_mps2, double total_b_uT, double dip_deg, const ReferenceField& reference,
                       const QcTolerances& tolerances, const QcChecks& checks = {});

}  // namespace plumb::survey
