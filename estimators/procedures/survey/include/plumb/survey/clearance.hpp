// Anti-collision: how close the reference well (the one being drilled) is to an offset well,
// weighed against how well both positions are known. The ISCWSA separation rule (Sawaryn et al.,
// "Well-Collision-Avoidance Separation Rule", SPE 187073, 2019), as the ISCWSA standard set of
// wellpaths for evaluating clearance scenarios (revision 4, 2017) calculates it:
//
//   at each reference station, the offset well's point of 3-D closest approach (along its
//   minimum-curvature arcs, closest_approach.hpp), centre-to-centre distance D and unit vector u;
//   each well's position uncertainty along u, its pedal curve radius sigma = sqrt(u' C u) (1 sigma;
//   the offset's covariance interpolated between its stations);
//   sigma_S = sqrt(sigma_ref^2 + sigma_off^2)   (the two wells' errors independent);
//   SF = (D - R_ref - R_off - S_m) / (k sqrt(sigma_S^2 + sigma_pa^2))
//
// with R the hole radii, S_m the surface margin (0.3 m), k the confidence scaling factor (3.5) and
// sigma_pa the projection-ahead uncertainty (0.5 m: the bit is ahead of the last survey). SF < 1
// means the wells' uncertainty regions, so scaled, overlap: the rule's limit. The minimum allowable
// separation distance is MASD = R_ref + R_off + S_m + k sqrt(sigma_S^2 + sigma_pa^2), the ellipse
// separation D - MASD (negative when SF < 1).
//
// Checked against the ISCWSA set (tests/data/iscwsa_clearance, docs/surveys.md "Anti-collision").
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "plumb/survey/closest_approach.hpp"
#include "plumb/survey/survey.hpp"

namespace plumb::survey {

// The ISCWSA separation rule's constants (SPE 187073; the values the ISCWSA clearance set uses).
struct SeparationRule {
  double k = 3.5;                  // confidence scaling factor
  double sigma_pa_m = 0.5;         // projection-ahead uncertainty, 1 sigma
  double surface_margin_m = 0.3;   // S_m
};

// Throws std::invalid_argument for k <= 0, a negative sigma_pa or margin, or numbers not finite.
void check_rule(const SeparationRule& rule);

struct ClearanceWell {
  std::string name;
  std::vector<WellPoint> stations;  // increasing measured depth, positions in the frame all wells share
  double radius_m = 0;              // the hole's radius (half its diameter)
  // The covariance at a point between two stations (`course` and `course + 1`), as the well's
  // error model gives it there; unset, it is interpolated linearly in measured depth.
  std::function<Eigen::Matrix3d(std::size_t course, const WellPoint& point)> covariance_between;
};

// One reference station against one offset well.
struct StationClearance {
  WellPoint reference;             // the reference station
  WellPoint offset;                // the offset well's point of closest approach
  double centre_to_centre_m = 0;   // D
  double horizontal_bearing_deg = 0;  // from the reference station toward the offset point, from north, [0, 360)
  // The offset point's direction in the plane normal to the reference well, clockwise from the
  // high side looking down the hole (from north near vertical): the travelling cylinder's angle.
  double high_side_bearing_deg = 0;
  double reference_sigma_m = 0, offset_sigma_m = 0;  // pedal curve radii along the centre-to-centre line
  double sigma_s_m = 0;            // sqrt(reference^2 + offset^2)
  double boundary_m = 0;           // k sqrt(sigma_S^2 + sigma_pa^2)
  double separation_m = 0;         // D - R_ref - R_off - S_m
  double ellipse_separation_m = 0; // D - MASD
  double masd_m = 0;               // minimum allowable separation distance
  double separation_factor = 0;
};

// The separation of one reference point (with its hole radius) from an offset well. Where the
// centres coincide (a sidetrack at its kick-off) there is no direction: each well's largest
// uncertainty counts, the worst case. Throws std::invalid_argument for an offset without stations
// or a bad rule.
StationClearance station_clearance(const WellPoint& reference, double reference_radius_m, const ClearanceWell& offset,
                                   const SeparationRule& rule);

// Every station of the reference well against the offset well.
std::vector<StationClearance> clearance(const ClearanceWell& reference, const ClearanceWell& offset,
                                        const SeparationRule& rule);

// A survey's row, or all its rows, as a clearance well's stations (the position covariance of every
// term).
WellPoint well_point(const SurveyRow& row);
std::vector<WellPoint> well_points(const std::vector<SurveyRow>& rows);

// A survey as a clearance well: its stations, and between them its error model at the point
// (Survey::uncertainty_between; the survey is copied and kept by the well).
ClearanceWell clearance_well(const Survey& survey, std::string name, double radius_m);

// The levels a directional driller is told: below the warning SF (1.5 by default) drilling on
// needs a plan; below the alarm SF (1.0, the rule's limit) it stops.
enum class ClearanceLevel { Clear, Warning, Alarm };
struct ClearanceLevels {
  double warning_sf = 1.5, alarm_sf = 1.0;
};
// Throws std::invalid_argument unless both are finite and warning >= alarm.
void check_levels(const ClearanceLevels& levels);
ClearanceLevel clearance_level(double separation_factor, const ClearanceLevels& levels);
std::string to_string(ClearanceLevel level);  // "clear", "warning", "alarm"

}  // namespace plumb::survey
