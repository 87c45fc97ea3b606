// Multi-station analysis: a constant axial magnetometer bias (drill-string magnetisation along the
// tool axis, the largest magnetic survey error) estimated from a run's stations, as MWD contractors'
// multi-station analysis does: every station's |B| and dip residuals against the reference field
// are linear in the bias (to first order), with a sensitivity set by the station's attitude.
//   |B|' - |B| = b Bz/|B|,   Bz/|B| = cos(dip) sinI cosA + sin(dip) cosI   (docs/conventions.md frames)
//   dip' - dip = b (cosI / |B| - sin(dip) Bz/|B|^2) / cos(dip)
// Weighted least squares over the stations gives b and its sigma; the azimuth each station would
// have without the bias follows from the closed-form attitude's own sensitivity to b.
#pragma once

#include <string>
#include <vector>

#include "plumb/survey/quality.hpp"
#include "plumb/survey/survey.hpp"

namespace plumb::survey {

struct AxialBiasEstimate {
  bool valid = false;
  double bias_uT = 0;           // along the tool's z axis (toward the bit)
  double sd_uT = 0;
  std::size_t stations = 0;     // stations with a measured field
  double rms_b_before_uT = 0, rms_b_after_uT = 0;    // |B| residuals before and after removing it
  double rms_dip_before_deg = 0, rms_dip_after_deg = 0;
  std::string reason;           // why not valid
};

// `sd_total_b_uT` and `sd_dip_deg` weight the two residuals (a station's measurement noise).
AxialBiasEstimate estimate_axial_bias(const std::vector<Station>& stations, const ReferenceField& reference,
                                      double sd_total_b_uT = 0.05, double sd_dip_deg = 0.05);

// The magnetic azimuth a station would have measured without an axial bias `bias_uT`, from the
// closed-form attitude of docs/conventions.md in the reference field.
double azimuth_without_axial_bias(double inclination_deg, double magnetic_azimuth_deg, double bias_uT,
                                  const ReferenceField& reference);

}  // namespace plumb::survey
