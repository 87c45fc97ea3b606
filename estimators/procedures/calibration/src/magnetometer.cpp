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

namespace {

// What each station gives the fit: gravity's direction (from the calibrated accelerometers) with
// its standard error, and the raw magnetometer vector.
struct StationVectors {
  std::vector<Eigen::Vector3d> gravity_dir, raw;
  std::vector<double> sigma_g;
};

// The starting point: hard and soft iron from the ellipsoid, the mean sin(dip), and each
// station's standard errors of |B| and of the dip.
struct StartingPoint {
  Eigen::Vector3d centre;
  Eigen::Matrix3d S0;
  double sin_dip0 = 0;
  std::vector<double> sigma_b, sigma_d;
};

// Gravity direction per station needs calibrated accelerometers: fitted here, or the base's.
void fit_accelerometers(const std::vector<StationAverage>& averages, const MagnetometerOptions& options, Result& r,
                        std::vector<std::string>& warnings) {
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

StationVectors station_vectors(const std::vector<StationAverage>& averages, const MagnetometerOptions& options,
                               const Result& r) {
  const auto n = averages.size();
  StationVectors v{std::vector<Eigen::Vector3d>(n), std::vector<Eigen::Vector3d>(n), std::vector<double>(n)};
  for (std::size_t s = 0; s < n; ++s) {
    const double dT = detail::station_dT(r.model, averages[s]);
    const Eigen::Vector3d f = r.model.accelerometer.apply(averages[s].accel, dT);
    if (!(f.norm() > 0.5 * options.g))
      throw CalibrationError("station '" + averages[s].station.name + "': calibrated |f| = " + detail::format(f.norm()) +
                             " m/s^2 is not gravity (accelerometer coefficients wrong?)");
    v.gravity_dir[s] = -f.normalized();
    const Eigen::Vector3d fse = r.model.accelerometer.sensitivity * averages[s].accel_se.asDiagonal() * Eigen::Vector3d::Ones();
    v.sigma_g[s] = fse.norm() / f.norm();
    v.raw[s] = averages[s].mag;
  }
  return v;
}

// The lower-triangular factor assumes the magnetometer axes lie within a few degrees of the
// accelerometers' (the fit then turns S).
StartingPoint starting_point(const std::vector<StationAverage>& averages, const StationVectors& v,
                             const MagnetometerOptions& options) {
  const auto n = averages.size();
  detail::check_spread(v.raw, "magnetometer");
  StartingPoint p;
  Eigen::Matrix3d shape;
  fit_ellipsoid(v.raw, options.total_field_ut, p.centre, shape);
  p.S0 = lower_factor(shape);
  p.sigma_b.resize(n);
  p.sigma_d.resize(n);
  for (std::size_t s = 0; s < n; ++s) {
    const Eigen::Vector3d B = p.S0 * (v.raw[s] - p.centre);
    p.sin_dip0 += v.gravity_dir[s].dot(B.normalized());
    p.sigma_b[s] = std::max((p.S0.transpose() * B.normalized()).cwiseProduct(averages[s].mag_se).norm(),
                            1e-12 * options.total_field_ut);
    p.sigma_d[s] = std::hypot(p.sigma_b[s] / options.total_field_ut, v.sigma_g[s]);
  }
  p.sin_dip0 /= static_cast<double>(n);
  return p;
}

// Hard iron, soft iron and sin(dip) (13 parameters) such that |B| is the total field and the dip
// the same at every station, each residual weighed by its standard error.
LmResult fit_iron(const StationVectors& v, const StartingPoint& p, const MagnetometerOptions& options) {
  const auto n = v.raw.size();
  const VectorFn residuals = [&](const Eigen::VectorXd& th) -> Eigen::VectorXd {
    const Eigen::Vector3d b = th.head<3>();
    Eigen::Matrix3d S;
    for (int row = 0; row < 3; ++row) S.row(row) = th.segment<3>(3 + 3 * row).transpose();
    Eigen::VectorXd res(2 * static_cast<Eigen::Index>(n));
    for (std::size_t s = 0; s < n; ++s) {
      const Eigen::Vector3d B = S * (v.raw[s] - b);
      const auto k = static_cast<Eigen::Index>(2 * s);
      res[k] = (B.norm() - options.total_field_ut) / p.sigma_b[s];
      res[k + 1] = (v.gravity_dir[s].dot(B) / B.norm() - th[12]) / p.sigma_d[s];
    }
    return res;
  };
  Eigen::VectorXd th(13), typical(13);
  th.head<3>() = p.centre;
  for (int row = 0; row < 3; ++row) th.segment<3>(3 + 3 * row) = p.S0.row(row).transpose();
  th[12] = p.sin_dip0;
  const double s_scale = p.S0.diagonal().cwiseAbs().maxCoeff();
  typical << Eigen::Vector3d::Constant(options.total_field_ut / s_scale), Eigen::VectorXd::Constant(9, s_scale), 1.0;
  LmOptions lo;
  lo.scale_by_residual_variance = true;
  lo.min_relative_singular_value = 1e-6;
  return levenberg_marquardt(
      residuals, th, typical,
      "the " + std::to_string(n) + " positions do not determine hard and soft iron and the frame (turn the tool "
      "through more directions, including about the field)", lo);
}

void store_magnetometer(const LmResult& lm, Result& r) {
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
}

// |B| residual per station, a warning for each station whose |B| or dip misfits, and the summary.
void report_fit(const std::vector<StationAverage>& averages, const StationVectors& v, const LmResult& lm,
                const MagnetometerOptions& options, Result& r, std::vector<std::string>& warnings) {
  const auto n = averages.size();
  double rms = 0;
  for (std::size_t s = 0; s < n; ++s) {
    StationResidual res;
    res.station = averages[s].station.name;
    const Eigen::Vector3d B = r.model.magnetometer.apply(v.raw[s], detail::station_dT(r.model, averages[s]));
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
        warnings.push_back("station '" + averages[s].station.name + "': " + (k == 0 ? "|B|" : "dip") + " misfit is " +
                           detail::format(std::abs(z) / std::max(s_res, 1.0)) +
                           " times the typical residual (magnetic disturbance or moving?)");
    }
  r.summary = "Magnetometer calibration from " + std::to_string(n) + " static positions: |B| residual rms " +
              detail::format(r.residual_rms) + " uT, dip " + detail::format(std::asin(std::clamp(lm.x[12], -1.0, 1.0)) / kDeg) +
              " deg, chi2/dof " + detail::format(lm.dof > 0 ? lm.chi2 / lm.dof : 0) + ".";
}

}  // namespace

Outcome magnetometer(const std::vector<StationAverage>& averages, const MagnetometerOptions& options) {
  return detail::run_guarded([&](std::vector<std::string>& warnings) {
    const auto n = averages.size();
    if (n < static_cast<std::size_t>(options.min_stations))
      throw CalibrationError("the magnetometer calibration needs at least " + std::to_string(options.min_stations) +
                             " static positions spread over all directions, got " + std::to_string(n));
    Result r;
    detail::fill_identity(r, options);
    detail::check_temperature_range(options.base, averages, warnings);
    if (options.calibrate_accelerometers) fit_accelerometers(averages, options, r, warnings);
    const StationVectors v = station_vectors(averages, options, r);
    const StartingPoint start = starting_point(averages, v, options);
    const LmResult lm = fit_iron(v, start, options);
    store_magnetometer(lm, r);
    report_fit(averages, v, lm, options, r, warnings);
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
