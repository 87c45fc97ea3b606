#include "error_prediction.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "plumb/core/attitude.hpp"
#include "procedure_common.hpp"

namespace plumb::calibration::detail {

namespace {

// Reference field for the azimuth (docs/conventions.md reference scenario): the accelerometer
// procedures do not touch the magnetometers, so only G moves the azimuth here.
constexpr double kTotalB = 48.4;
constexpr double kDipDeg = 45.5;

struct Point {
  double inc = 0, tf = 0, azi = 0, T = 0;
  bool azimuth = false;
};

double inclination_deg(const Eigen::Vector3d& f) { return std::atan2(std::hypot(f.x(), f.y()), -f.z()) / kDeg; }

double azimuth_deg(const Eigen::Vector3d& f, const Eigen::Vector3d& B) {
  const Eigen::Vector3d G = -f;
  return std::atan2(G.norm() * (G.x() * B.y() - G.y() * B.x()),
                    B.z() * (G.x() * G.x() + G.y() * G.y()) - G.z() * (G.x() * B.x() + G.y() * B.y())) /
         kDeg;
}

}  // namespace

std::vector<double> temperatures_over(double min_c, double max_c) {
  std::vector<double> t{min_c};
  for (double T = std::ceil(min_c / 10) * 10; T < max_c; T += 10)
    if (T > min_c) t.push_back(T);
  t.push_back(max_c);
  return t;
}

ErrorPrediction predict_error(const ModelOf& model_of, const Eigen::VectorXd& theta, const Eigen::MatrixXd& covariance,
                              const std::vector<std::string>& names, const std::vector<double>& temperatures_c, double g) {
  ErrorPrediction out;
  const auto n = theta.size();
  const CalibrationModel fitted = model_of(theta);
  // Models at theta +- one standard deviation of each parameter: central differences with that
  // step are exact for the quadratic part and cheap (built once, applied at every point).
  std::vector<CalibrationModel> plus, minus;
  Eigen::VectorXd step(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    step[i] = std::sqrt(std::max(0.0, covariance(i, i)));
    Eigen::VectorXd tp = theta, tm = theta;
    tp[i] += step[i];
    tm[i] -= step[i];
    plus.push_back(model_of(tp));
    minus.push_back(model_of(tm));
  }
  std::vector<Point> points;
  for (double T : temperatures_c)
    for (double inc = 0; inc <= 180; inc += 15)
      for (double tf = 0; tf < 360; tf += 30) {
        points.push_back({inc, tf, 0, T, false});
        if (inc >= 10 && inc <= 120)
          for (double azi = 0; azi < 360; azi += 90) points.push_back({inc, tf, azi, T, true});
      }
  double worst_inc = -1, worst_azi = -1;
  Eigen::VectorXd worst_J;
  for (const auto& p : points) {
    const double dT = p.T - fitted.reference_temp_c;
    const Eigen::Vector3d f = -gravity_tool(p.inc * kDeg, p.tf * kDeg, g);
    const Eigen::Vector3d B = field_tool(p.inc * kDeg, p.azi * kDeg, p.tf * kDeg, kTotalB, kDipDeg * kDeg);
    const Eigen::Vector3d u = fitted.accelerometer.raw_for(f, dT);
    Eigen::VectorXd J(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (step[i] == 0) {
        J[i] = 0;
        continue;
      }
      const Eigen::Vector3d fp = plus[k].accelerometer.apply(u, dT), fm = minus[k].accelerometer.apply(u, dT);
      const double d = p.azimuth ? wrap_deg_180(azimuth_deg(fp, B) - azimuth_deg(fm, B))
                                 : inclination_deg(fp) - inclination_deg(fm);
      J[i] = d / (2 * step[i]);
    }
    const double sd = std::sqrt(std::max(0.0, J.dot(covariance * J)));
    if (p.azimuth) {
      if (3 * sd > worst_azi) {
        worst_azi = 3 * sd;
        out.azimuth_at_inclination_deg = p.inc;
      }
    } else if (3 * sd > worst_inc) {
      worst_inc = 3 * sd;
      out.inclination_at_deg = p.inc;
      out.toolface_at_deg = p.tf;
      out.temperature_at_c = p.T;
      worst_J = J;
    }
  }
  out.valid = worst_inc >= 0;
  out.inclination_deg = std::max(0.0, worst_inc);
  out.azimuth_deg = std::max(0.0, worst_azi);
  if (worst_J.size() == n) {
    // Contributions by parameter group ("accel.sensor_scale_temp" = all its orders and axes), each
    // with the correlations inside the group: single parameters of a polynomial in temperature are
    // strongly correlated and each alone would overstate its share.
    std::vector<std::string> groups;
    std::vector<std::vector<Eigen::Index>> members;
    for (Eigen::Index i = 0; i < n; ++i) {
      std::string g = names[static_cast<std::size_t>(i)];
      g = g.substr(0, g.rfind('.'));
      while (!g.empty() && std::isdigit(static_cast<unsigned char>(g.back()))) g.pop_back();
      const auto it = std::find(groups.begin(), groups.end(), g);
      if (it == groups.end()) {
        groups.push_back(g);
        members.push_back({i});
      } else {
        members[static_cast<std::size_t>(it - groups.begin())].push_back(i);
      }
    }
    for (std::size_t k = 0; k < groups.size(); ++k) {
      double var = 0;
      for (Eigen::Index a : members[k])
        for (Eigen::Index b : members[k]) var += worst_J[a] * covariance(a, b) * worst_J[b];
      out.contributions.emplace_back(groups[k], 3 * std::sqrt(std::max(0.0, var)));
    }
    std::sort(out.contributions.begin(), out.contributions.end(),
              [](const auto& a, const auto& b) { return a.second > b.second; });
    if (out.contributions.size() > 4) out.contributions.resize(4);
  }
  std::ostringstream grid;
  grid << "inclination 0..180 deg every 15, toolface every 30 deg (azimuth: inclination 10..120, every 90 deg), "
       << temperatures_c.size() << " temperatures " << format(temperatures_c.front()) << ".."
       << format(temperatures_c.back()) << " degC";
  out.grid = grid.str();
  return out;
}

void require_predicted_error(const ErrorPrediction& p, double max_deg) {
  if (!p.valid || p.inclination_deg <= max_deg) return;
  std::string why;
  for (std::size_t i = 0; i < p.contributions.size() && i < 2; ++i)
    why += (i ? ", " : "") + p.contributions[i].first + " " + format(p.contributions[i].second, 2) + " deg";
  throw CalibrationError("predicted inclination error " + format(p.inclination_deg, 3) + " deg (3 sd, at inclination " +
                         format(p.inclination_at_deg) + " deg, " + format(p.temperature_at_c) + " degC) exceeds " +
                         "the tolerance " + format(max_deg, 3) + " deg (--max-error-deg); largest contributions: " + why);
}

}  // namespace plumb::calibration::detail
