// docs/methods.md section 2: 24-position accelerometer calibration with temperature.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <Eigen/Cholesky>

#include "plumb/calibration/fit.hpp"
#include "plumb/calibration/procedures.hpp"
#include "plumb/calibration/thermometer.hpp"
#include "plumb/calibration/triad_fit.hpp"
#include "error_prediction.hpp"
#include "procedure_common.hpp"
#include "rotation_average.hpp"
#include "temperature_fit.hpp"

namespace plumb::calibration {

namespace {

// Checks that a run has each of the 24 positions once; returns them by face * 4 + rotation / 90.
std::vector<const StationAverage*> complete_run(const std::vector<const StationAverage*>& run, const std::string& run_name) {
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
  for (int f = 0; f < 6; ++f)
    for (int r = 0; r < 4; ++r)
      if (!slots[static_cast<std::size_t>(f * 4 + r)]) {
        Orientation o;
        o.axis = f / 2;
        o.sign = f % 2 ? -1 : 1;
        o.rotation_deg = 90 * r;
        throw CalibrationError(context + "position " + o.label() + " is missing");
      }
  return std::vector<const StationAverage*>(slots.begin(), slots.end());
}

// 1. Thermometer, against the average of the reference thermometers.
void fit_thermometer_step(const std::vector<StationAverage>& averages, const TwentyFourOptions& options, Result& r,
                          std::vector<std::string>& warnings) {
  std::vector<ThermometerPoint> points;
  for (const auto& a : averages) {
    if (!a.has_temperature || a.station.reference_temps_c.empty()) continue;
    double ref = 0;
    for (double t : a.station.reference_temps_c) ref += t;
    points.push_back({a.raw_temp_c, ref / static_cast<double>(a.station.reference_temps_c.size())});
  }
  if (points.empty()) {
    warnings.push_back("no reference thermometer readings: thermometer correction taken from the base coefficients");
    return;
  }
  const ThermometerFit th = fit_thermometer(points, options.nonlinear_above_c);
  r.model.thermometer = th.coefficients;
  detail::add_parameters(r.parameters, "thermometer.", {"c0", "c1", "c2", "c3"}, Eigen::Vector4d(th.coefficients.data()),
                         th.covariance, "");
  r.summary += "Thermometer: degree " + std::to_string(th.degree) + " fit over " + std::to_string(points.size()) +
               " stations, " + detail::format(th.min_c) + " to " + detail::format(th.max_c) + " degC, residual rms " +
               detail::format(th.rms_c) + " degC. ";
}

// 2a. One temperature run: its 24 positions, its temperature (a station far from it is a suspect
// for the robust average), rotations averaged, six-face fit.
detail::RunFit fit_run(const std::string& name, const std::vector<const StationAverage*>& run, bool several_runs,
                       const TwentyFourOptions& options, Result& r, std::vector<std::string>& warnings) {
  const auto slots = complete_run(run, name);
  check_orientations(run, options.max_orientation_error_deg);
  detail::RunFit rf;
  rf.name = name;
  std::vector<double> temps;
  for (const auto* s : run)
    if (s->has_temperature) temps.push_back(r.model.corrected_temperature(s->raw_temp_c));
  std::vector<const StationAverage*> unstable;
  if (temps.size() == run.size()) {
    double mean = 0;
    for (double t : temps) mean += t;
    rf.temperature_c = mean / static_cast<double>(temps.size());
    for (std::size_t i = 0; i < run.size(); ++i)
      if (std::abs(temps[i] - rf.temperature_c) > options.max_run_temp_spread_c) {
        unstable.push_back(run[i]);
        warnings.push_back("station '" + run[i]->station.name + "' is at " + detail::format(temps[i]) + " degC, " +
                           detail::format(temps[i] - rf.temperature_c) + " degC from its run '" + name + "' (" +
                           detail::format(rf.temperature_c) + " degC): temperature not stable");
      }
  } else {
    rf.temperature_c = options.reference_temp_c;
    if (several_runs)
      throw CalibrationError("run '" + name + "' has stations without temperature: the temperature "
                             "dependence needs the thermometer channel");
  }
  const detail::RotationAverage ra = detail::robust_rotation_average(slots, name.empty() ? "" : "run '" + name + "': ", unstable);
  for (const auto& d : ra.dropped) {
    r.dropped.push_back(d);
    warnings.push_back(d);
  }
  rf.fit = fit_six_faces(ra.faces, options.g);
  return rf;
}

// 2. Every temperature run fitted, in order of temperature; two runs at one temperature refused.
std::vector<detail::RunFit> fit_runs(const std::vector<StationAverage>& averages, const TwentyFourOptions& options,
                                     Result& r, std::vector<std::string>& warnings) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<const StationAverage*>> runs;
  for (const auto& a : averages) {
    if (!runs.count(a.station.run)) order.push_back(a.station.run);
    runs[a.station.run].push_back(&a);
  }
  if (averages.empty()) throw CalibrationError("no stations");
  std::vector<detail::RunFit> fits;
  for (const auto& name : order) fits.push_back(fit_run(name, runs[name], order.size() > 1, options, r, warnings));
  std::sort(fits.begin(), fits.end(),
            [](const detail::RunFit& a, const detail::RunFit& b) { return a.temperature_c < b.temperature_c; });
  for (std::size_t i = 1; i < fits.size(); ++i)
    if (fits[i].temperature_c - fits[i - 1].temperature_c < 1.0)
      throw CalibrationError("runs '" + fits[i - 1].name + "' and '" + fits[i].name + "' are at the same temperature (" +
                             detail::format(fits[i].temperature_c) + " degC): give each temperature one run");
  return fits;
}

// What the error prediction needs of the fitted accelerometer model: its parameters, their
// covariance (inflated when the residuals exceed the noise) and names, and the model they make.
struct FittedParameters {
  Eigen::VectorXd theta;
  Eigen::MatrixXd covariance;
  std::vector<std::string> names;
  double cov_scale = 1;
  detail::ModelOf model_of;
};

// 3a. One temperature run: no temperature coefficients, the run's temperature +-5 degC calibrated.
FittedParameters fit_one_temperature(const detail::RunFit& f, const TwentyFourOptions& options, Result& r,
                                     std::vector<std::string>& warnings) {
  if (options.temperature_order > 0)
    throw CalibrationError("temperature order " + std::to_string(options.temperature_order) + " needs at least " +
                           std::to_string(options.temperature_order + 1) + " temperature runs, got 1");
  r.model.accelerometer = triad_from_vector(f.fit.params);
  r.model.reference_temp_c = f.temperature_c;
  r.model.temp_min_c = f.temperature_c - 5;
  r.model.temp_max_c = f.temperature_c + 5;
  detail::add_parameters(r.parameters, "accel.", triad_parameter_names(), f.fit.params, f.fit.covariance);
  warnings.push_back("one temperature run: no temperature coefficients; calibrated range " +
                     detail::format(r.model.temp_min_c) + " to " + detail::format(r.model.temp_max_c) + " degC");
  r.residual_rms = std::sqrt(f.fit.chi2 / 3);
  FittedParameters p;
  p.cov_scale = std::max(1.0, f.fit.chi2 / 3);
  p.theta = f.fit.params;
  p.covariance = f.fit.covariance;
  p.names = triad_parameter_names();
  const CalibrationModel base = r.model;
  p.model_of = [base](const Eigen::VectorXd& th) {
    CalibrationModel m = base;
    m.accelerometer = triad_from_vector(th);
    return m;
  };
  return p;
}

// 3b. Temperature dependence over the runs, in the sensors' own form (model version 2).
FittedParameters fit_over_temperatures(const std::vector<detail::RunFit>& fits, const TwentyFourOptions& options,
                                       Result& r, std::vector<std::string>& warnings) {
  const detail::TemperatureFit tf = detail::fit_temperature_model(fits, options.reference_temp_c, options.temperature_order);
  r.model.accelerometer = detail::triad_of(tf.theta, tf.order);
  r.model.temp_min_c = fits.front().temperature_c;
  r.model.temp_max_c = fits.back().temperature_c;
  detail::add_parameters(r.parameters, "accel.", tf.names, tf.theta, tf.covariance);
  r.residual_rms = std::sqrt(tf.chi2 / std::max(1, tf.dof));
  std::string evidence;
  for (std::size_t k = 0; k < tf.chi2_by_order.size(); ++k)
    evidence += (k ? ", " : "") + detail::format(tf.chi2_by_order[k]) + "/" + std::to_string(tf.dof_by_order[k]);
  r.summary += "Temperature model: each sensor's bias and scale factor as a polynomial of order " +
               std::to_string(tf.order) + " in temperature on its own output (" +
               (options.temperature_order > 0 ? std::string("order given") : "order chosen from the residuals") +
               "; chi2/dof by order " + evidence + "). ";
  if (tf.dof > 0 && tf.chi2 / tf.dof > 10)
    warnings.push_back("the runs do not follow a temperature dependence of order " + std::to_string(tf.order) +
                       ": chi2/dof = " + detail::format(tf.chi2 / tf.dof) +
                       " (coefficients kept; the predicted error is scaled by it)");
  FittedParameters p;
  p.cov_scale = std::max(1.0, tf.chi2 / std::max(1, tf.dof));
  p.theta = tf.theta;
  p.covariance = tf.covariance;
  p.names = tf.names;
  const CalibrationModel base = r.model;
  const int order = tf.order;
  p.model_of = [base, order](const Eigen::VectorXd& th) {
    CalibrationModel m = base;
    m.accelerometer = detail::triad_of(th, order);
    return m;
  };
  return p;
}

}  // namespace

Outcome twenty_four_position(const std::vector<StationAverage>& averages, const TwentyFourOptions& options) {
  return detail::run_guarded([&](std::vector<std::string>& warnings) {
    Result r;
    detail::fill_identity(r, options);
    r.model.reference_temp_c = options.reference_temp_c;
    fit_thermometer_step(averages, options, r, warnings);
    const std::vector<detail::RunFit> fits = fit_runs(averages, options, r, warnings);
    FittedParameters p = fits.size() == 1 ? fit_one_temperature(fits.front(), options, r, warnings)
                                          : fit_over_temperatures(fits, options, r, warnings);
    for (auto& n : p.names) n = "accel." + n;
    // 4. The error this calibration leaves over its temperature range, and the residuals.
    r.predicted = detail::predict_error(p.model_of, p.theta, p.cov_scale * p.covariance, p.names,
                                        detail::temperatures_over(r.model.temp_min_c, r.model.temp_max_c), options.g);
    r.summary += "24-position calibration: " + std::to_string(fits.size()) + " temperature run(s) from " +
                 detail::format(fits.front().temperature_c) + " to " + detail::format(fits.back().temperature_c) +
                 " degC, " + std::to_string(averages.size()) + " stations.";
    r.residuals = detail::accel_residuals(r.model, options.nominal, averages, options.g,
                                          options.warn_direction_error_deg, warnings);
    r.split = detail::split_residuals(r.model, averages);
    detail::require_predicted_error(r.predicted, options.max_error_deg);
    return r;
  });
}

Outcome twenty_four_position(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                             const TwentyFourOptions& options) {
  return detail::from_samples(samples, stations, options, options.settle,
                              [](const std::vector<StationAverage>& a, const TwentyFourOptions& o) { return twenty_four_position(a, o); });
}

}  // namespace plumb::calibration
