// Position uncertainty along the survey, propagated station by station the way the ISCWSA error
// model does it (Williamson, SPE 67616, 2000): every error source gives, at each station, a change
// of (measured depth, inclination, azimuth); the minimum-curvature path turns it into a change of
// position; sources that are independent from station to station ("random") add as covariances,
// sources common to every station ("systematic") add as vectors first, then as a covariance.
//
// Terms in (names as in the ISCWSA MWD model where one exists):
//   random per station:  depth reading (each station's md_sd_m), inclination and azimuth noise (each
//                        station's attitude sigma from its estimator);
//   systematic:          DEC  declination uncertainty (true and grid azimuths only),
//                        DSF  depth scale factor (relative),
//                        AMIL axial magnetic interference / axial magnetometer bias (uT): azimuth
//                             change b sinI sinA / (B cos dip),
//                        ABZ  axial accelerometer bias (m/s^2): inclination and azimuth change from
//                             the closed-form attitude's own sensitivity (dI = -sinI b / g).
// Not in: the radial (x, y) accelerometer and magnetometer biases and the scale-factor terms of the
// full MWD model (they depend on each station's toolface; the estimators' sigma covers noise, not
// calibration residuals), misalignment (SAG, MX, MY), and the depth terms DREF/DST: give them as
// per-station depth sigma if they matter.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "plumb/survey/minimum_curvature.hpp"

namespace plumb::survey {

struct StationSigma {
  double md_sd_m = 0;
  double inclination_sd_deg = 0;
  double azimuth_sd_deg = 0;
  double magnetic_azimuth_deg = 0;  // for AMIL's weighting (the azimuth the magnetometers measured)
};

struct ErrorModel {
  double declination_sd_deg = 0;   // DEC (0 for a magnetic survey: the reference is magnetic north itself)
  double depth_scale_sd = 0;       // DSF, relative (e.g. 2e-4)
  double axial_bias_sd_uT = 0;     // AMIL
  double axial_accel_bias_sd_mps2 = 0;  // ABZ
  double total_b_uT = 50;          // reference field for AMIL's and ABZ's weighting
  double dip_deg = 60;
  double gravity_mps2 = 9.80665;
};

// The factor that turns 1-sigma semi-axes of a 2-D normal into its 95 % ellipse: sqrt(chi2_2(0.95))
// = sqrt(-2 ln 0.05). (A "2 sigma" ellipse, factor 2, holds 86.5 % of a 2-D normal, not 95 %.)
inline constexpr double kEllipse95Factor = 2.4477468306808161;

struct PositionUncertainty {
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // north, east, down (m^2)
  double north_sd_m = 0, east_sd_m = 0, tvd_sd_m = 0;
  double major_sd_m = 0, minor_sd_m = 0;  // horizontal ellipse, 1 sigma semi-axes
  double major_azimuth_deg = 0;           // direction of the major axis, [0, 180)
};

// Fills the standard deviations and the horizontal ellipse from `covariance`.
void describe_covariance(PositionUncertainty& u);

// The uncertainty at every station (the first station, the tie-in, has none of its own).
// `stations` and `sigma` have the same length; measured depths increase strictly.
std::vector<PositionUncertainty> propagate_uncertainty(const std::vector<StationGeometry>& stations,
                                                       const std::vector<StationSigma>& sigma, const ErrorModel& model);

// Whether `error` (north, east) lies inside the horizontal ellipse of `u` scaled by `factor`
// (Mahalanobis distance <= factor).
bool inside_ellipse(const PositionUncertainty& u, double error_north_m, double error_east_m, double factor);

}  // namespace plumb::survey
