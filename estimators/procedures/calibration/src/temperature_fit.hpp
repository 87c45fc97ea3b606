// The temperature model of the 24-position procedure in the sensors' own form (model version 2,
// docs/calibration.md 4.3): each accelerometer's scale factor and bias drift with temperature on
// that sensor's output, before the matrix that maps sensor axes to tool axes (docs/methods.md section 3:
// output_i = k_i(T) (a_i + b_i(T) + ...)). Private to the library.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/calibration/triad_fit.hpp"
#include "plumb/core/calibration_model.hpp"

namespace plumb::calibration::detail {

struct RunFit {
  std::string name;
  double temperature_c = 0;
  TriadFit fit;
};

inline constexpr int kMaxTemperatureOrder = 3;

// Parameters theta: bias b0 (3), S0 row-major (9), k2 (3), then the bias drift c_p (3 per order
// p = 1..P, raw units per degC^p), then the sensor scale drift s_p (3 per order). With
// s(d) = 1 + sum s_p d^p and b(d) = b0 + sum c_p d^p a run at d = T - T0 reads
//   u = s .* (b(d) + S0^-1 (a + k2 .* a^2)),  i.e. its six-face fit is bias s .* b(d), S0 diag(1/s), k2.
struct TemperatureFit {
  int order = 1;
  Eigen::VectorXd theta;
  Eigen::MatrixXd covariance;
  double chi2 = 0;
  int dof = 0;
  std::vector<double> chi2_by_order;   // index p-1: chi2 of the fit of order p (the selection's evidence)
  std::vector<int> dof_by_order;
  std::vector<std::string> names;      // "bias.x" ... "bias_temp2.z", "sensor_scale_temp1.x" ...
};

// The triad model (version 2 terms) that theta of the given order stands for.
TriadModel triad_of(const Eigen::VectorXd& theta, int order);

// Fits orders 1..max over the runs (weighted by each run's full 15x15 covariance). order > 0
// forces that order; order == 0 chooses it from the residuals: the lowest order p such that
// going to p + 1 does not lower chi2 by more than the 0.1 % point of chi2 with 6 degrees of
// freedom (22.46), i.e. the six further coefficients explain nothing that noise would not.
// Throws CalibrationError when there are too few runs for the order.
TemperatureFit fit_temperature_model(const std::vector<RunFit>& runs, double T0, int order);

}  // namespace plumb::calibration::detail
