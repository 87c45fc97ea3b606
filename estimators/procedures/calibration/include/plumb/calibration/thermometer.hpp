// Thermometer correction against reference thermometers (docs/methods.md section 2): T = c0 + c1 t + c2 t^2 +
// c3 t^3 with t the tool's raw reading and T the average of the reference thermometers.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

namespace plumb::calibration {

struct ThermometerPoint {
  double raw_c = 0;         // tool thermometer (station average)
  double reference_c = 0;   // average of the reference thermometers
};

struct ThermometerFit {
  std::array<double, 4> coefficients{0, 1, 0, 0};
  Eigen::Matrix4d covariance = Eigen::Matrix4d::Zero();
  int degree = 1;
  double rms_c = 0;          // residual
  double min_c = 0, max_c = 0;   // reference range covered
};

// The degree follows the data: a cubic when the references go above nonlinear_above_c (the
// thermometer's non-linear range) and there are at least four distinct temperatures, otherwise
// linear (an offset only for a single temperature). Throws CalibrationError without points.
ThermometerFit fit_thermometer(const std::vector<ThermometerPoint>& points, double nonlinear_above_c = 175);

}  // namespace plumb::calibration
