// docs/methods.md section 3: six-position calibration of the accelerometers.
#include <algorithm>
#include <array>
#include <cmath>

#include "plumb/calibration/procedures.hpp"
#include "plumb/calibration/triad_fit.hpp"
#include "error_prediction.hpp"
#include "procedure_common.hpp"

namespace plumb::calibration {

namespace {

// Exactly one station per face; a missing or repeated face names itself and its stations.
std::array<const StationAverage*, 6> assign_faces(const std::vector<const StationAverage*>& stations,
                                                  const std::string& context) {
  std::array<const StationAverage*, 6> faces{};
  for (const auto* s : stations) {
    const Orientation& o = s->station.orientation;
    if (!o.known())
      throw CalibrationError(context + "station '" + s->station.name +
                             "' has no orientation; the 6-position procedure needs +x -x +y -y +z -z");
    auto& slot = faces[static_cast<std::size_t>(o.face())];
    if (slot)
      throw CalibrationError(context + "position " + face_label(o.face()) + " is repeated: stations '" +
                             slot->station.name + "' and '" + s->station.name + "'");
    slot = s;
  }
  for (int f = 0; f < 6; ++f)
    if (!faces[static_cast<std::size_t>(f)])
      throw CalibrationError(context + "position " + face_label(f) + " is missing");
  return faces;
}

}  // namespace

Outcome six_position(const std::vector<StationAverage>& averages, const CommonOptions& options) {
  return detail::run_guarded([&](std::vector<std::string>& warnings) {
    std::vector<const StationAverage*> stations;
    for (const auto& a : averages) stations.push_back(&a);
    const auto faces = assign_faces(stations, "");
    check_orientations(stations, options.max_orientation_error_deg);

    FaceAverages fa;
    for (std::size_t f = 0; f < 6; ++f) {
      fa.mean[f] = faces[f]->accel;
      fa.se[f] = faces[f]->accel_se.cwiseMax(1e-12 * faces[f]->accel.cwiseAbs().maxCoeff());
    }
    const TriadFit fit = fit_six_faces(fa, options.g);

    Result r;
    detail::fill_identity(r, options);
    r.model.accelerometer = triad_from_vector(fit.params);
    r.model.accelerometer.bias_temp.setZero();
    r.model.accelerometer.scale_temp.setZero();
    // Coefficients for the temperature of the stations (no temperature terms): the calibrated
    // range is that temperature with a small margin.
    std::vector<double> temps;
    for (const auto& a : averages)
      if (a.has_temperature) temps.push_back(r.model.corrected_temperature(a.raw_temp_c));
    if (!temps.empty() && temps.size() == averages.size()) {
      const auto [lo, hi] = std::minmax_element(temps.begin(), temps.end());
      double mean = 0;
      for (double t : temps) mean += t;
      r.model.reference_temp_c = mean / static_cast<double>(temps.size());
      r.model.temp_min_c = *lo - 5;
      r.model.temp_max_c = *hi + 5;
    }

    detail::add_parameters(r.parameters, "accel.", triad_parameter_names(), fit.params, fit.covariance);
    detail::add_parameters(r.parameters, "accel.", method_parameter_names(), fit.method_params, fit.method_covariance);
    if (fit.chi2 > 30)
      warnings.push_back("the three redundant bias equations disagree: chi2 = " + detail::format(fit.chi2) +
                         " for 3 degrees of freedom (unsettled station or orientation error?)");
    r.residual_rms = std::sqrt(fit.chi2 / 3);
    r.residuals = detail::accel_residuals(r.model, options.nominal, averages, options.g,
                                          options.warn_direction_error_deg, warnings);
    r.summary = "6-position accelerometer calibration from 6 stations; redundant-equation chi2 " +
                detail::format(fit.chi2) + " (3 dof).";
    // Predicted error: the station noise through the fit, inflated when the redundant equations
    // disagree more than that noise explains (chi2 / dof > 1).
    const CalibrationModel base = r.model;
    std::vector<std::string> names = triad_parameter_names();
    for (auto& n : names) n = "accel." + n;
    r.predicted = detail::predict_error(
        [base](const Eigen::VectorXd& th) {
          CalibrationModel m = base;
          m.accelerometer = triad_from_vector(th);
          return m;
        },
        fit.params, std::max(1.0, fit.chi2 / 3) * fit.covariance, names,
        detail::temperatures_over(r.model.temp_min_c, r.model.temp_max_c), options.g);
    detail::require_predicted_error(r.predicted, options.max_error_deg);
    return r;
  });
}

Outcome six_position(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                     const CommonOptions& options) {
  return detail::from_samples(samples, stations, options, options.settle,
                              [](const std::vector<StationAverage>& a, const CommonOptions& o) { return six_position(a, o); });
}

Procedure parse_procedure(const std::string& name) {
  if (name == "6pos") return Procedure::SixPosition;
  if (name == "24pos") return Procedure::TwentyFourPosition;
  if (name == "lsq") return Procedure::LeastSquares;
  if (name == "mag") return Procedure::Magnetometer;
  throw CalibrationError("unknown procedure '" + name + "' (choose 6pos, 24pos, lsq or mag)");
}

const char* procedure_name(Procedure p) {
  switch (p) {
    case Procedure::SixPosition: return "6pos";
    case Procedure::TwentyFourPosition: return "24pos";
    case Procedure::LeastSquares: return "lsq";
    case Procedure::Magnetometer: return "mag";
  }
  return "?";
}

SettleOptions default_settle(Procedure p) {
  SettleOptions s;
  s.check_mag = p == Procedure::Magnetometer;
  return s;
}

}  // namespace plumb::calibration
