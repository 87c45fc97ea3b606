// Azimuth references. The estimators measure magnetic azimuth (docs/conventions.md: north is magnetic);
// true azimuth = magnetic + declination (east positive); grid azimuth = true - convergence, the
// grid convergence being the angle from true north to grid north, positive when grid north lies
// east of true north (the sign every survey program states beside its grid). Every output of a
// survey names its reference.
#pragma once

#include <optional>
#include <string>

namespace plumb::survey {

enum class AzimuthReference { Magnetic, True, Grid };

std::string to_string(AzimuthReference r);  // "magnetic", "true", "grid"
// Empty for any other text.
std::optional<AzimuthReference> parse_azimuth_reference(const std::string& text);

struct NorthCorrections {
  double declination_deg = 0;     // magnetic -> true
  double declination_sd_deg = 0;  // its uncertainty (a systematic error of every station)
  double convergence_deg = 0;     // true -> grid
  bool declination_known = false;
  bool convergence_known = false;
};

// A magnetic azimuth in `to`, in [0, 360). Throws std::invalid_argument when a needed correction
// was not given (a true or grid survey without a declination is an error, never a silent 0).
double convert_magnetic_azimuth(double magnetic_deg, AzimuthReference to, const NorthCorrections& c);

// What turns an azimuth in `from` into a true azimuth (true = azimuth + this): 0 for true, the
// convergence for grid, the declination for magnetic, or 0 where that declination is not known
// (magnetic north taken for true). A gyro's errors depend on the true azimuth, whatever the
// survey's reference.
double true_azimuth_offset_deg(AzimuthReference from, const NorthCorrections& c);

}  // namespace plumb::survey
