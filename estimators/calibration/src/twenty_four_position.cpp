// METHODS.md 2: 24-position accelerometer calibration with temperature.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <Eigen/Cholesky>

#include "plumb/calibration/fit.hpp"
#include "plumb/calibration/procedures.hpp"
#include "plumb/calibration/thermometer.hpp"
#include "plumb/calibration/triad_fit.hpp"
#include "procedure_common.hpp"

namespace plumb::calibration {

namespace {

struct RunFit {
  std::string name;
  double temperature_c = 0;
  TriadFit fit;
};

// Checks that a run has each of the 24 positions once, and averages the four rotations of each face.
FaceAverages average_rotations(const std::vector<const StationAverage*>& run, const std::string& run_name) {
  const std::string context = run_name.empty() ? "" : "run '" + run_name + "': ";
  std::array<const StationAverage*, 24> slots{};
  for (const auto* s : run) {
    const Orientation& o = s->station.orientation;
    if (!o.known())
      throw CalibrationError(context + "station '" + s->station.name +
                             "' has no orientation; the 24-position procedure needs e.g. +x@90");
    auto& slot = slots[static_cast<std::size_t>(o.face() * 4 + o.rotation_deg / 90)];
    if (slot)
      throw CalibrationError(context + "position " + face_label(o.face()) + "@" + std::to_string(o.rotation_deg) + " is repeated: stations '" + slot->station.name +
                             "' and '" + s->station.name + "'");
    slot = s;
  }
  FaceAverages fa;
  for (int f = 0; f < 6; ++f) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero(), var = Eigen::Vector3d::Zero();
    for (int r = 0; r < 4; ++r) {
      const auto* s = slots[static_cast<std::size_t>(f * 4 + r)];
      if (!s) {
        Orientation o;
        o.axis = f / 2;
        o.sign = f % 2 ? -1 : 1;
        o.rotation_deg = 90 * r;
        throw CalibrationError(context + "position " + o.label() + " is missing");
      }
      sum += s->accel;
      var += s->accel_se.cwiseAbs2();
    }
    fa.mean[static_cast<std::size_t>(f)] = sum / 4;
    fa.se[static_cast<std::size_t>(f)] = (var.cwiseSqrt() / 4).cwiseMax(1e-12 * sum.cwiseAbs().maxCoeff());
  }
  return fa;
}

// The temperature model over the runs: bias(T) = b0 + bt dT, S(T) = diag(1 + st dT) S0, k2 fixed.
// Parameters: b0 (3), bt (3), S0 (9 row-major), st (3), k2 (3).
constexpr int kTempParams = 21;

TriadVector predict(const Eigen::VectorXd& th, double dT) {
  TriadVector p;
  p.segment<3>(0) = th.segment<3>(0) + th.segment<3>(3) * dT;
  for (int r = 0; r < 3; ++r) p.segment<3>(3 + 3 * r) = th.segment<3>(6 + 3 * r) * (1 + th[15 + r] * dT);
  p.segment<3>(12) = th.segment<3>(18);
  return p;
}

}  // namespace

Outcome twenty_four_position(const std::vector<StationAverage>& averages, const TwentyFourOptions& options) {
  return detail::run_guarded([&](std::vector<std::string>& warnings) {
    Result r;
    detail::fill_identity(r, options);
    r.model.reference_temp_c = options.reference_temp_c;

    // 1. Thermometer, against the average of the reference thermometers.
    std::vector<ThermometerPoint> points;
    for (const auto& a : averages) {
      if (!a.has_temperature || a.station.reference_temps_c.empty()) continue;
      double ref = 0;
      for (double t : a.station.reference_temps_c) ref += t;
      points.push_back({a.raw_temp_c, ref / static_cast<double>(a.station.reference_temps_c.size())});
    }
    if (!points.empty()) {
      const ThermometerFit th = fit_thermometer(points, options.nonlinear_above_c);
      r.model.thermometer = th.coefficients;
      detail::add_parameters(r.parameters, "thermometer.", {"c0", "c1", "c2", "c3"},
                             Eigen::Vector4d(th.coefficients.data()), th.covariance, "");
      r.summary += "Thermometer: degree " + std::to_string(th.degree) + " fit over " + std::to_string(points.size()) +
                   " stations, " + detail::format(th.min_c) + " to " + detail::format(th.max_c) +
                   " degC, residual rms " + detail::format(th.rms_c) + " degC. ";
    } else {
      warnings.push_back("no reference thermometer readings: thermometer correction taken from the base coefficients");
    }

    // 2. Per temperature run: 24 positions, rotations averaged, six-face fit.
    std::vector<std::string> order;
    std::map<std::string, std::vector<const StationAverage*>> runs;
    for (const auto& a : averages) {
      if (!runs.count(a.station.run)) order.push_back(a.station.run);
      runs[a.station.run].push_back(&a);
    }
    if (averages.empty()) throw CalibrationError("no stations");
    std::vector<RunFit> fits;
    for (const auto& name : order) {
      const auto& run = runs[name];
      const FaceAverages fa = average_rotations(run, name);
      check_orientations(run, options.max_orientation_error_deg);
      RunFit rf;
      rf.name = name;
      rf.fit = fit_six_faces(fa, options.g);
      std::vector<double> temps;
      for (const auto* s : run)
        if (s->has_temperature) temps.push_back(r.model.corrected_temperature(s->raw_temp_c));
      if (temps.size() == run.size()) {
        double mean = 0;
        for (double t : temps) mean += t;
        rf.temperature_c = mean / static_cast<double>(temps.size());
        for (std::size_t i = 0; i < run.size(); ++i)
          if (std::abs(temps[i] - rf.temperature_c) > options.max_run_temp_spread_c)
            warnings.push_back("station '" + run[i]->station.name + "' is at " + detail::format(temps[i]) +
                               " degC, " + detail::format(temps[i] - rf.temperature_c) + " degC from its run '" +
                               name + "' (" + detail::format(rf.temperature_c) + " degC): temperature not stable");
      } else {
        rf.temperature_c = options.reference_temp_c;
        if (order.size() > 1)
          throw CalibrationError("run '" + name + "' has stations without temperature: the temperature "
                                 "dependence needs the thermometer channel");
      }
      fits.push_back(rf);
    }
    std::sort(fits.begin(), fits.end(), [](const RunFit& a, const RunFit& b) { return a.temperature_c < b.temperature_c; });
    for (std::size_t i = 1; i < fits.size(); ++i)
      if (fits[i].temperature_c - fits[i - 1].temperature_c < 1.0)
        throw CalibrationError("runs '" + fits[i - 1].name + "' and '" + fits[i].name + "' are at the same temperature (" +
                               detail::format(fits[i].temperature_c) + " degC): give each temperature one run");

    // 3. Temperature dependence over the runs.
    const double T0 = options.reference_temp_c;
    if (fits.size() == 1) {
      const auto& f = fits.front();
      r.model.accelerometer = triad_from_vector(f.fit.params);
      r.model.reference_temp_c = f.temperature_c;
      r.model.temp_min_c = f.temperature_c - 5;
      r.model.temp_max_c = f.temperature_c + 5;
      detail::add_parameters(r.parameters, "accel.", triad_parameter_names(), f.fit.params, f.fit.covariance);
      warnings.push_back("one temperature run: no temperature coefficients; calibrated range " +
                         detail::format(r.model.temp_min_c) + " to " + detail::format(r.model.temp_max_c) + " degC");
      r.residual_rms = std::sqrt(f.fit.chi2 / 3);
    } else {
      std::vector<Eigen::Matrix<double, kTriadParams, kTriadParams>> whiten;
      for (const auto& f : fits) {
        Eigen::LLT<TriadCovariance> llt(f.fit.covariance);
        if (llt.info() != Eigen::Success) throw CalibrationError("run '" + f.name + "': singular fit covariance");
        whiten.push_back(llt.matrixL().solve(TriadCovariance::Identity()));
      }
      const VectorFn residuals = [&](const Eigen::VectorXd& th) -> Eigen::VectorXd {
        Eigen::VectorXd res(kTriadParams * static_cast<Eigen::Index>(fits.size()));
        for (std::size_t k = 0; k < fits.size(); ++k)
          res.segment<kTriadParams>(kTriadParams * static_cast<Eigen::Index>(k)) =
              whiten[k] * (predict(th, fits[k].temperature_c - T0) - fits[k].fit.params);
        return res;
      };
      // Start from the run nearest T0 with no temperature dependence.
      const auto& nearest = *std::min_element(fits.begin(), fits.end(), [&](const RunFit& a, const RunFit& b) {
        return std::abs(a.temperature_c - T0) < std::abs(b.temperature_c - T0);
      });
      Eigen::VectorXd th = Eigen::VectorXd::Zero(kTempParams), typical(kTempParams);
      th.segment<3>(0) = nearest.fit.params.segment<3>(0);
      th.segment<9>(6) = nearest.fit.params.segment<9>(3);
      th.segment<3>(18) = nearest.fit.params.segment<3>(12);
      const double s_scale = nearest.fit.params.segment<9>(3).cwiseAbs().maxCoeff();
      const double b_scale = 1.0 / s_scale;  // raw units per m/s^2
      typical << Eigen::Vector3d::Constant(b_scale), Eigen::Vector3d::Constant(1e-3 * b_scale),
          Eigen::VectorXd::Constant(9, s_scale), Eigen::Vector3d::Constant(1e-4), Eigen::Vector3d::Constant(1e-5);
      const LmResult lm = levenberg_marquardt(residuals, th, typical,
                                              "temperature runs do not determine the temperature coefficients");
      const Eigen::VectorXd& x = lm.x;
      TriadModel& acc = r.model.accelerometer;
      acc = triad_from_vector(predict(x, 0));
      acc.bias_temp = x.segment<3>(3);
      acc.scale_temp = x.segment<3>(15);
      r.model.temp_min_c = fits.front().temperature_c;
      r.model.temp_max_c = fits.back().temperature_c;
      // Parameters: the model at T0, then the temperature terms.
      std::vector<int> at_T0;
      for (int i = 0; i < 3; ++i) at_T0.push_back(i);
      for (int i = 0; i < 9; ++i) at_T0.push_back(6 + i);
      for (int i = 0; i < 3; ++i) at_T0.push_back(18 + i);
      Eigen::VectorXd v0(15);
      Eigen::MatrixXd c0(15, 15);
      for (int i = 0; i < 15; ++i) {
        v0[i] = x[at_T0[static_cast<std::size_t>(i)]];
        for (int j = 0; j < 15; ++j) c0(i, j) = lm.covariance(at_T0[static_cast<std::size_t>(i)], at_T0[static_cast<std::size_t>(j)]);
      }
      detail::add_parameters(r.parameters, "accel.", triad_parameter_names(), v0, c0);
      detail::add_parameters(r.parameters, "accel.", {"bias_temp.x", "bias_temp.y", "bias_temp.z"}, x.segment<3>(3),
                             lm.covariance.block<3, 3>(3, 3), "raw/degC");
      detail::add_parameters(r.parameters, "accel.", {"scale_temp.x", "scale_temp.y", "scale_temp.z"},
                             x.segment<3>(15), lm.covariance.block<3, 3>(15, 15), "1/degC");
      r.residual_rms = std::sqrt(lm.chi2 / std::max(1, lm.dof));
      if (lm.dof > 0 && lm.chi2 / lm.dof > 10)
        warnings.push_back("the runs do not follow a linear temperature dependence: chi2/dof = " +
                           detail::format(lm.chi2 / lm.dof));
    }
    r.summary += "24-position calibration: " + std::to_string(fits.size()) + " temperature run(s) from " +
                 detail::format(fits.front().temperature_c) + " to " + detail::format(fits.back().temperature_c) +
                 " degC, " + std::to_string(averages.size()) + " stations.";
    r.residuals = detail::accel_residuals(r.model, options.nominal, averages, options.g,
                                          options.warn_direction_error_deg, warnings);
    return r;
  });
}

Outcome twenty_four_position(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                             const TwentyFourOptions& options) {
  return detail::from_samples(samples, stations, options, options.settle,
                              [](const std::vector<StationAverage>& a, const TwentyFourOptions& o) { return twenty_four_position(a, o); });
}

}  // namespace plumb::calibration
