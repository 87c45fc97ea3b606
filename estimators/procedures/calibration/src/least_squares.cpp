// Accelerometer calibration from static positions in unknown orientations: |S (u - bias)| = g.
#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "plumb/calibration/fit.hpp"
#include "plumb/calibration/procedures.hpp"
#include "procedure_common.hpp"
#include "static_fit.hpp"

namespace plumb::calibration {

namespace detail {

Eigen::Matrix3d lower_from(const Eigen::VectorXd& th, Eigen::Index at) {
  Eigen::Matrix3d L = Eigen::Matrix3d::Zero();
  L(0, 0) = th[at];
  L(1, 0) = th[at + 1];
  L(1, 1) = th[at + 2];
  L(2, 0) = th[at + 3];
  L(2, 1) = th[at + 4];
  L(2, 2) = th[at + 5];
  return L;
}

StaticFit fit_static_accelerometers(const std::vector<StationAverage>& averages, const LeastSquaresOptions& options,
                                    std::vector<std::string>& warnings) {
  const auto n = averages.size();
  if (n < static_cast<std::size_t>(options.min_stations))
    throw CalibrationError("the least-squares calibration needs at least " + std::to_string(options.min_stations) +
                           " static positions spread over all directions, got " + std::to_string(n));
  std::vector<Eigen::Vector3d> points;
  for (const auto& a : averages) points.push_back(a.accel);
  check_spread(points, "accelerometer");
  Eigen::Vector3d centre;
  Eigen::Matrix3d shape;
  fit_ellipsoid(points, options.g, centre, shape);
  const Eigen::Matrix3d L0 = lower_factor(shape);

  // Weights: the noise of |f| at each station, through the initial sensitivity.
  std::vector<double> sigma(n);
  for (std::size_t s = 0; s < n; ++s) {
    const Eigen::Vector3d f = L0 * (points[s] - centre);
    const Eigen::Vector3d grad = (L0.transpose() * f.normalized());
    sigma[s] = std::max(grad.cwiseProduct(averages[s].accel_se).norm(), 1e-12 * options.g);
  }
  const VectorFn residuals = [&](const Eigen::VectorXd& th) -> Eigen::VectorXd {
    const Eigen::Vector3d b = th.head<3>();
    const Eigen::Matrix3d L = lower_from(th, 3);
    Eigen::VectorXd r(static_cast<Eigen::Index>(n));
    for (std::size_t s = 0; s < n; ++s) r[static_cast<Eigen::Index>(s)] = ((L * (points[s] - b)).norm() - options.g) / sigma[s];
    return r;
  };
  Eigen::VectorXd th(9), typical(9);
  th << centre, L0(0, 0), L0(1, 0), L0(1, 1), L0(2, 0), L0(2, 1), L0(2, 2);
  const double s_scale = L0.diagonal().cwiseAbs().maxCoeff();
  typical << Eigen::Vector3d::Constant(1 / s_scale), Eigen::VectorXd::Constant(6, s_scale);
  LmOptions lo;
  lo.scale_by_residual_variance = true;
  lo.min_relative_singular_value = 1e-6;
  const LmResult lm = levenberg_marquardt(
      residuals, th, typical,
      "the " + std::to_string(n) + " positions are not spread over enough directions to determine bias and "
      "sensitivity (turn the tool through all directions)", lo);
  StaticFit out;
  out.bias = lm.x.head<3>();
  out.sensitivity = lower_from(lm.x, 3);
  out.params = lm.x;
  out.covariance = lm.covariance;
  out.chi2 = lm.chi2;
  out.dof = lm.dof;
  const double s = lm.dof > 0 ? std::sqrt(lm.chi2 / lm.dof) : 1;
  for (std::size_t k = 0; k < n; ++k) {
    const double z = lm.residuals[static_cast<Eigen::Index>(k)];
    if (std::abs(z) > 4 * std::max(s, 1.0))
      warnings.push_back("station '" + averages[k].station.name + "': |f| misfit " + format(z * sigma[k]) +
                         " m/s^2 is " + format(std::abs(z) / std::max(s, 1.0)) + " times the typical residual (moving?)");
  }
  return out;
}

void check_spread(const std::vector<Eigen::Vector3d>& points, const std::string& what) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : points) cov += (p - mean) * (p - mean).transpose();
  const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvalues();
  // Positions over the whole sphere give a ratio near 1; positions in one plane (turned about one
  // axis only) give 0 and leave that axis' bias and scale undetermined.
  if (!(ev[0] > 0.01 * ev[2]))
    throw CalibrationError("the " + std::to_string(points.size()) + " positions are not spread over all directions: the " +
                           what + " readings lie close to a plane (spread ratio " + format(ev[0] / std::max(ev[2], 1e-300)) +
                           "); turn the tool through all directions, including up and down");
}

void check_temperature_range(const CalibrationModel& base, const std::vector<StationAverage>& averages,
                             std::vector<std::string>& warnings) {
  for (const auto& a : averages) {
    if (!a.has_temperature) continue;
    const double T = base.corrected_temperature(a.raw_temp_c);
    if (T < base.temp_min_c || T > base.temp_max_c)
      warnings.push_back("station '" + a.station.name + "' is at " + format(T) + " degC, outside the calibrated range " +
                         format(base.temp_min_c) + " to " + format(base.temp_max_c) + " degC");
  }
}

}  // namespace detail

Outcome least_squares(const std::vector<StationAverage>& averages, const LeastSquaresOptions& options) {
  return detail::run_guarded([&](std::vector<std::string>& warnings) {
    detail::check_temperature_range(options.base, averages, warnings);
    const detail::StaticFit fit = detail::fit_static_accelerometers(averages, options, warnings);
    Result r;
    detail::fill_identity(r, options);
    TriadModel& acc = r.model.accelerometer;
    acc = TriadModel{};
    acc.bias = fit.bias;
    acc.sensitivity = fit.sensitivity;
    detail::add_parameters(r.parameters, "accel.",
                           {"bias.x", "bias.y", "bias.z", "sensitivity.xx", "sensitivity.yx", "sensitivity.yy",
                            "sensitivity.zx", "sensitivity.zy", "sensitivity.zz"},
                           fit.params, fit.covariance);
    r.residual_rms = 0;
    for (const auto& a : averages) {
      const double e = (acc.apply(a.accel, 0)).norm() - options.g;
      r.residual_rms += e * e;
    }
    r.residual_rms = std::sqrt(r.residual_rms / static_cast<double>(averages.size()));
    r.residuals = detail::accel_residuals(r.model, options.nominal, averages, options.g,
                                          options.warn_direction_error_deg, warnings);
    r.summary = "Least-squares accelerometer calibration from " + std::to_string(averages.size()) +
                " static positions in unknown orientations: |f| residual rms " + detail::format(r.residual_rms) +
                " m/s^2, chi2/dof " + detail::format(fit.dof > 0 ? fit.chi2 / fit.dof : 0) +
                ". The tool frame is the accelerometers': x along the x accelerometer, y in the plane of x and y.";
    return r;
  });
}

Outcome least_squares(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                      const LeastSquaresOptions& options) {
  return detail::from_samples(samples, stations, options, options.settle,
                              [](const std::vector<StationAverage>& a, const LeastSquaresOptions& o) { return least_squares(a, o); });
}

}  // namespace plumb::calibration
