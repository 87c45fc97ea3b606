// The static-position fits shared by the least-squares and magnetometer procedures (private).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/calibration/procedures.hpp"

namespace plumb::calibration::detail {

struct StaticFit {
  Eigen::Vector3d bias = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sensitivity = Eigen::Matrix3d::Identity();
  Eigen::VectorXd params;
  Eigen::MatrixXd covariance;
  double chi2 = 0;
  int dof = 0;
};

// Lower-triangular S from parameters th[at .. at+5] = S00 S10 S11 S20 S21 S22.
Eigen::Matrix3d lower_from(const Eigen::VectorXd& th, Eigen::Index at);

StaticFit fit_static_accelerometers(const std::vector<StationAverage>& averages, const LeastSquaresOptions& options,
                                    std::vector<std::string>& warnings);

// Throws CalibrationError when the readings do not cover all directions.
void check_spread(const std::vector<Eigen::Vector3d>& points, const std::string& what);

// A warning per station whose temperature lies outside the base coefficients' calibrated range.
void check_temperature_range(const CalibrationModel& base, const std::vector<StationAverage>& averages,
                             std::vector<std::string>& warnings);

}  // namespace plumb::calibration::detail
