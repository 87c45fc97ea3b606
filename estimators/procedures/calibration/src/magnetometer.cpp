// Magnetometer calibration: hard iron (bias) and soft iron (S) from static positions of a rotation
// sequence, with |B| = total field and the dip constraint G.B / (|G||B|) = sin(dip) at every station.
#include <algorithm>
#include <cmath>

#include "plumb/calibration/fit.hpp"
#include "plumb/calibration/procedures.hpp"
#include "plumb/core/attitude.hpp"
#include "procedure_common.hpp"
#include "static_fit.hpp"

namespace plumb::calibration {

Outcome magnetometer(const std::vector<StationAverage>& averages, const MagnetometerOptions& options) {
  return detail::run_guarded([&](std::vector<std::string>& warnings) {
    const auto n = averages.size();
    if (n < static_cast<std::size_t>(options.min_stations))
      throw CalibrationError("the magnetometer calibration needs at least " + std::to_string(options.min_stations) +
                             " static positions spread over all directions, got " + std::to_string(n));
    Result r;
    detail::fill_identity(r, options);
    detail::check_temperature_range(options.base, averages, warnings);

    // Gravity direction per station, from calibrated accelerometers.
    if (options.calibrate_accelerometers) {
      LeastSquaresOptions lo;
      static_cast<CommonOptions&>(lo) = options;
      lo.min_stations = options.min_stations;
      const detail::StaticFit acc = detail::fit_static_accelerometers(averages, lo, warnings);
      r.model.accelerometer = TriadModel{};
      r.model.accelerometer.bias = acc.bias;
      r.model.accelerometer.sensitivity = acc.sensitivity;
      detail::add_parameters(r.parameters, "accel.",
                             {"bias.x", "bias.y", "bias.z", "sensitivity.xx", "sensitivity.yx", "sensitivity.yy",
                              "sensitivity.zx", "sensitivity.zy", "sensitivity.zz"},
                             acc.params, acc.covariance);
    }
    std::vector<Eigen::Vector3d> gravity_dir(n), raw(n);
    std::vector<double> sigma_g(n);
    for (std::size_t s = 0; s < n; ++s) {
      const double dT = detail::station_dT(r.model, averages[s]);
      const Eigen::Vector3d f = r.model.accelerometer.apply(averages[s].accel, dT);
      if (!(f.norm() > 0.5 * options.g))
        throw CalibrationError("station '" + averages[s].station.name + "': calibrated |f| = " +
                               detail::format(f.norm()) + " m/s^2 is not gravity (accelerometer coefficients wrong?)");
      gravity_dir[s] = -f.normalized();
      const Eigen::Vector3d fse = r.model.accelerometer.sensitivity * averages[s].accel_se.asDiagonal() *
                                  Eigen::Vector3d::Ones();
      sigma_g[s] = fse.norm() / f.norm();
      raw[s] = averages[s].mag;
    }

    // Initial hard and soft iron from the ellipsoid; the lower-triangular factor assumes the
    // magnetometer axes lie within a few degrees of the accelerometers' (the fit then turns S).
    detail::check_spread(raw, "magnetometer");
    Eigen::Vector3d centre;
    Eigen::Matrix3d shape;
    fit_ellipsoid(raw, options.total_field_ut, centre, shape);
    const Eigen::Matrix3d S0 = lower_factor(shape);
    double sin_dip0 = 0;
    std::vector<double> sigma_b(n), sigma_d(n);
    for (std::size_t s = 0; s < n; ++s) {
      const Eigen::Vector3d B = S0 * (raw[s] - centre);
      sin_dip0 += gravity_dir[s].dot(B.normalized());
      sigma_b[s] = std::max((S0.transpose() * B.normalized()).cwiseProduct(averages[s].mag_se).norm(),
                            1e-12 * options.total_field_ut);
      sigma_d[s] = std::hypot(sigma_b[s] / options.total_field_ut, sigma_g[s]);
    }
    sin_dip0 /= static_cast<double>(n);

    const VectorFn residuals = [&](const Eigen::VectorXd& th) -> Eigen::VectorXd {
      const Eigen::Vector3d b = th.head<3>();
      Eigen::Matrix3d S;
      for (int row = 0; row < 3; ++row) S.row(row) = th.segment<3>(3 + 3 * row).transpose();
      Eigen::VectorXd res(2 * static_cast<Eigen::Index>(n));
      for (std::size_t s = 0; s < n; ++s) {
        const Eigen::Vector3d B = S * (raw[s] - b);
        const auto k = static_cast<Eigen::Index>(2 * s);
        res[k] = (B.norm() - options.total_field_ut) / sigma_b[s];
        res[k + 1] = (gravity_dir[s].dot(B) / B.norm() - th[12]) / sigma_d[s];
      }
      return res;
    };
    Eigen::VectorXd th(13), typical(13);
    th.head<3>() = centre;
    for (int row = 0; row < 3; ++row) th.segment<3>(3 + 3 * row) = S0.row(row).transpose();
    th[12] = sin_dip0;
    const double s_scale = S0.diagonal().cwiseAbs().maxCoeff();
    typical << Eigen::Vector3d::Constant(options.total_field_ut / s_scale), Eigen::VectorXd::Constant(9, s_scale), 1.0;
    LmOptions lo;
    lo.scale_by_residual_variance = true;
    lo.min_relative_singular_value = 1e-6;
    const LmResult lm = levenberg_marquardt(
        residuals, th, typical,
        "the " + std::to_string(n) + " positions do not determine hard and soft iron and the frame (turn the tool "
        "through more directions, including about the field)", lo);

    TriadModel& mag = r.model.magnetometer;
    mag = TriadModel{};
    mag.bias = lm.x.head<3>();
    for (int row = 0; row < 3; ++row) mag.sensitivity.row(row) = lm.x.segment<3>(3 + 3 * row).transpose();
    std::vector<std::string> names = {"bias.x", "bias.y", "bias.z"};
    const char* const ax = "xyz";
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) names.push_back(std::string("sensitivity.") + ax[i] + ax[j]);
    names.push_back("sin_dip");
    detail::add_parameters(r.parameters, "mag.", names, lm.x, lm.covariance);

    double rms = 0;
    for (std::size_t s = 0; s < n; ++s) {
      StationResidual res;
      res.station = averages[s].station.name;
      const Eigen::Vector3d B = mag.apply(raw[s], detail::station_dT(r.model, averages[s]));
      res.norm_error = B.norm() - options.total_field_ut;
      rms += res.norm_error * res.norm_error;
      r.residuals.push_back(res);
    }
    r.residual_rms = std::sqrt(rms / static_cast<double>(n));
    const double s_res = lm.dof > 0 ? std::sqrt(lm.chi2 / lm.dof) : 1;
    for (std::size_t s = 0; s < n; ++s)
      for (int k = 0; k < 2; ++k) {
        const double z = lm.residuals[static_cast<Eigen::Index>(2 * s + static_cast<std::size_t>(k))];
        if (std::abs(z) > 4 * std::max(s_res, 1.0))
          warnings.push_back("station '" + averages[s].station.name + "': " + (k == 0 ? "|B|" : "dip") +
                             " misfit is " + detail::format(std::abs(z) / std::max(s_res, 1.0)) +
                             " times the typical residual (magnetic disturbance or moving?)");
      }
    r.summary = "Magnetometer calibration from " + std::to_string(n) + " static positions: |B| residual rms " +
                detail::format(r.residual_rms) + " uT, dip " + detail::format(std::asin(std::clamp(lm.x[12], -1.0, 1.0)) / kDeg) +
                " deg, chi2/dof " + detail::format(lm.dof > 0 ? lm.chi2 / lm.dof : 0) + ".";
    return r;
  });
}

Outcome magnetometer(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                     const MagnetometerOptions& options) {
  SettleOptions settle = options.settle;
  settle.check_mag = true;  // the magnetometer must settle too
  return detail::from_samples(samples, stations, options, settle,
                              [](const std::vector<StationAverage>& a, const MagnetometerOptions& o) { return magnetometer(a, o); });
}

}  // namespace plumb::calibration
