// A survey: stations in measured-depth order, each quality-checked, turned into the well path by
// minimum curvature, with its position uncertainty. Rows never change once added (the path and the
// uncertainty at a station depend only on the stations above it), so a live survey publishes and
// appends each row once.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "plumb/survey/azimuth_reference.hpp"
#include "plumb/survey/iscwsa.hpp"
#include "plumb/survey/minimum_curvature.hpp"
#include "plumb/survey/quality.hpp"
#include "plumb/survey/uncertainty.hpp"

namespace plumb::survey {

// What was measured at one station (the inputs; everything else is derived from these).
struct Station {
  double t_s = 0;                      // time of the attitude (window end), s
  std::string tool_id;
  std::string source;                  // estimator name, or the file it came from
  double md_m = 0, md_sd_m = 0;
  double inclination_deg = 0, inclination_sd_deg = 0;
  double magnetic_azimuth_deg = 0, azimuth_sd_deg = 0;
  bool azimuth_valid = true;           // false near vertical (kept and flagged)
  double total_g_mps2 = std::numeric_limits<double>::quiet_NaN();
  double total_b_uT = std::numeric_limits<double>::quiet_NaN();
  double dip_deg = std::numeric_limits<double>::quiet_NaN();
  double toolface_deg = std::numeric_limits<double>::quiet_NaN();     // gravity toolface (NaN: not measured)
  double toolface_sd_deg = std::numeric_limits<double>::quiet_NaN();
  std::uint32_t windows = 1;           // attitude windows combined into the station (0: a listed station)
};

struct SurveyRow {
  std::uint32_t index = 0;             // 0-based position in the survey
  Station station;
  double azimuth_deg = 0;              // in `reference`
  AzimuthReference reference = AzimuthReference::Magnetic;
  QcResult qc;
  PathPoint point;
  PositionUncertainty uncertainty;     // every term: the error model's and the measured noise
  PositionUncertainty random_uncertainty;  // the random terms only
  // What the station's own angles are worth: the measured noise and every term of the error model
  // at this station (random and systematic), or the measured noise alone without a model.
  double inclination_total_sd_deg = 0, azimuth_total_sd_deg = 0;
  double inclination_random_sd_deg = 0, azimuth_random_sd_deg = 0;  // the noise and the random terms
  std::string warning;                 // e.g. azimuth ill-conditioned; empty when none
  ReferenceField field;                // the reference field of the QC and the error model
  std::string error_model;             // the tool code, or "plumb" (plumb's own propagation)
};

struct SurveyOptions {
  AzimuthReference reference = AzimuthReference::Magnetic;
  NorthCorrections north;
  ReferenceField field;
  QcTolerances tolerances;
  QcChecks checks;
  ErrorModel errors;                   // plumb's own terms; declination_sd_deg is taken from `north`
  // The ISCWSA model (a tool code); without one, plumb's own propagation of `errors`. Its
  // declination terms (AZ, DBH) are left out of a magnetic survey, whose north is magnetic north.
  std::optional<iscwsa::ToolCode> tool_code;
  // The survey program's later legs: from each depth on the stations are priced by its tool code,
  // each leg's systematic terms its own draw (iscwsa::Leg). They need tool_code, the first leg's.
  std::vector<iscwsa::Leg> later_legs;
  double latitude_deg = std::numeric_limits<double>::quiet_NaN();  // the gyro model's gyrocompass terms
  // The stations' own angle sigmas already hold what the tool code's terms describe: the strapdown
  // navigator's filter carries its drift since alignment in every row's sigma. Each station's sigma
  // then enters only by what it exceeds the model's angle sigma at that station (the excess
  // variance, inclination and azimuth each), so a station where the navigator knows it is blind
  // keeps its width, a normal one is not counted twice, and no station is held narrower than
  // either says. Without a tool code it does nothing.
  bool station_sigma_beyond_model = false;
  // The ISCWSA model's first station: a tie-in point (false) or a survey whose errors tilt the
  // half course below it (iscwsa::Field::first_station_surveyed).
  bool first_station_surveyed = false;
  // In the survey's reference; none: the closure azimuth of the last station (the well's direction),
  // every row's vertical section following it as stations are added.
  std::optional<double> section_azimuth_deg;
  Eigen::Vector3d tie_in = Eigen::Vector3d::Zero();  // position of the first station (north, east, tvd)
};

// The error model in a line: the tool code's name, each later leg's after it ("GYRO-NS (...); from
// MD 1230 m MWD (...)"), or "plumb" (plumb's own terms).
std::string error_model_text(const SurveyOptions& options);

// A station that cannot enter the survey's geometry: depth not increasing, angles out of range,
// numbers not finite. Its what() is one line naming the station.
struct StationError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// The measured depths (and angles) of two stations closer than this are the same station.
inline constexpr double kDuplicateDepthM = 1e-6;

class Survey {
 public:
  // Throws std::invalid_argument for options that cannot work (a true survey without declination,
  // tolerances <= 0, non-finite numbers).
  explicit Survey(SurveyOptions options);
  // Checks the station and appends it with its QC, path point and uncertainty; a failed QC is kept
  // and flagged. Throws StationError (and leaves the survey unchanged) for a station whose geometry
  // is impossible: depth going backwards or repeated, inclination outside [0, 180], azimuth not finite.
  const SurveyRow& add(const Station& station);
  // From the next station on, the survey is priced by `tool`, a leg of its own (a re-tuned
  // navigator's figures), down to the next leg given (SurveyOptions::later_legs); the stations
  // already added keep their uncertainty. Before any station it replaces the first leg's tool code.
  // Throws std::invalid_argument as the constructor does for a tool code that cannot work (a
  // gyrocompass without the latitude), or without a tool code to follow.
  void start_leg(iscwsa::ToolCode tool);
  // The tool code that prices a station at this depth: the last leg starting at or above it.
  const iscwsa::ToolCode* tool_code_at(double md_m) const;
  const std::vector<SurveyRow>& rows() const { return rows_; }
  // The position uncertainty at a point between stations `course` and `course + 1`, as if a station
  // had been surveyed there in the direction the path has (azimuth in the survey's reference): the
  // error model between stations, where a clearance scan finds an offset well's closest point.
  // Its measured noise is interpolated between the two stations'. Throws std::out_of_range for a
  // course the survey does not have.
  PositionUncertainty uncertainty_between(std::size_t course, double md_m, double inclination_deg,
                                          double azimuth_deg) const;
  const SurveyOptions& options() const { return options_; }
  std::size_t failed_qc() const { return failed_qc_; }
  // The vertical section's azimuth in use: the one given, else the last station's closure azimuth
  // (0 before a station has left the reference point).
  double section_azimuth_deg() const;
  bool section_azimuth_is_closure() const { return !options_.section_azimuth_deg.has_value(); }

 private:
  SurveyOptions options_;
  std::vector<SurveyRow> rows_;
  std::vector<StationGeometry> geometry_;
  std::vector<StationSigma> sigma_;
  void add_model_uncertainty(SurveyRow& row);
  // A tool code made ready for this survey: checked, its declination terms left out of a magnetic one.
  void prepare(iscwsa::ToolCode& tool) const;
  std::size_t failed_qc_ = 0;
};

}  // namespace plumb::survey
