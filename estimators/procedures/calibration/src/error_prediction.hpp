// The calibration's predicted error in use, from its parameters' covariance (private).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plumb/calibration/types.hpp"

namespace plumb::calibration::detail {

using ModelOf = std::function<CalibrationModel(const Eigen::VectorXd& theta)>;

// Propagates cov(theta) to the inclination (and azimuth, inclinations 10..120 deg) of the
// calibrated accelerometers over inclinations 0..180 deg, toolfaces and azimuths every 30 deg and
// the given temperatures; reports the worst 3-sigma values and the largest contributions.
// The raw outputs at each point are the fitted model's own (its inverse): what matters is how the
// coefficients' uncertainty moves the result, not the noise of one sample.
ErrorPrediction predict_error(const ModelOf& model_of, const Eigen::VectorXd& theta, const Eigen::MatrixXd& covariance,
                              const std::vector<std::string>& names, const std::vector<double>& temperatures_c, double g);

// Throws CalibrationError when the prediction exceeds max_deg (a procedure never yields such
// coefficients).
void require_predicted_error(const ErrorPrediction& p, double max_deg);

// Temperatures that cover a range: its ends and 10 degC steps between.
std::vector<double> temperatures_over(double min_c, double max_c);

}  // namespace plumb::calibration::detail
