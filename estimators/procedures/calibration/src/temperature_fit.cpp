#include "temperature_fit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "plumb/calibration/fit.hpp"
#include "plumb/calibration/types.hpp"

namespace plumb::calibration::detail {

namespace {

// Chi-square with 6 degrees of freedom exceeds this with probability 0.1 %.
constexpr double kChi2Six999 = 22.458;

Eigen::Index size_of(int order) { return 15 + 6 * order; }

TriadVector predict(const Eigen::VectorXd& th, int order, double d) {
  Eigen::Vector3d s = Eigen::Vector3d::Ones(), b = th.segment<3>(0);
  double dp = 1;
  for (int p = 1; p <= order; ++p) {
    dp *= d;
    b += th.segment<3>(15 + 3 * (p - 1)) * dp;
    s += th.segment<3>(15 + 3 * order + 3 * (p - 1)) * dp;
  }
  TriadVector out;
  out.segment<3>(0) = s.cwiseProduct(b);
  // S0 diag(1/s): column c of S0 divided by s_c.
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[3 + 3 * r + c] = th[3 + 3 * r + c] / s[c];
  out.segment<3>(12) = th.segment<3>(12);
  return out;
}

std::vector<std::string> names_of(int order) {
  std::vector<std::string> n = triad_parameter_names();
  const char* const ax = "xyz";
  for (int p = 1; p <= order; ++p)
    for (int i = 0; i < 3; ++i)
      n.push_back(std::string(p == 1 ? "bias_temp" : "bias_temp" + std::to_string(p)) + "." + ax[i]);
  for (int p = 1; p <= order; ++p)
    for (int i = 0; i < 3; ++i) n.push_back("sensor_scale_temp" + std::to_string(p) + "." + ax[i]);
  return n;
}

}  // namespace

TriadModel triad_of(const Eigen::VectorXd& th, int order) {
  TriadVector base;
  base = th.head<15>();
  TriadModel t = triad_from_vector(base);
  Eigen::Vector3d* bias_terms[3] = {&t.bias_temp, &t.bias_temp2, &t.bias_temp3};
  Eigen::Vector3d* scale_terms[3] = {&t.sensor_scale_temp1, &t.sensor_scale_temp2, &t.sensor_scale_temp3};
  for (int p = 1; p <= order; ++p) {
    *bias_terms[p - 1] = th.segment<3>(15 + 3 * (p - 1));
    *scale_terms[p - 1] = th.segment<3>(15 + 3 * order + 3 * (p - 1));
  }
  return t;
}

TemperatureFit fit_temperature_model(const std::vector<RunFit>& runs, double T0, int order) {
  const int n_runs = static_cast<int>(runs.size());
  if (order > kMaxTemperatureOrder)
    throw CalibrationError("temperature order " + std::to_string(order) + " is not supported (1 to " +
                           std::to_string(kMaxTemperatureOrder) + ", or 0 to choose it from the data)");
  // A polynomial of order p through the runs needs p + 1 temperatures.
  if (order > 0 && n_runs < order + 1)
    throw CalibrationError("temperature order " + std::to_string(order) + " needs at least " +
                           std::to_string(order + 1) + " temperature runs, got " + std::to_string(n_runs));
  const int max_order = order > 0 ? order : std::min(kMaxTemperatureOrder, n_runs - 1);
  const int min_order = order > 0 ? order : 1;

  std::vector<TriadCovariance> whiten;
  for (const auto& f : runs) {
    Eigen::LLT<TriadCovariance> llt(f.fit.covariance);
    if (llt.info() != Eigen::Success) throw CalibrationError("run '" + f.name + "': singular fit covariance");
    whiten.push_back(llt.matrixL().solve(TriadCovariance::Identity()));
  }
  // The run nearest T0 starts the fit with no temperature dependence.
  const auto& nearest = *std::min_element(runs.begin(), runs.end(), [&](const RunFit& a, const RunFit& b) {
    return std::abs(a.temperature_c - T0) < std::abs(b.temperature_c - T0);
  });
  const double s_scale = nearest.fit.params.segment<9>(3).cwiseAbs().maxCoeff();
  const double b_scale = 1.0 / s_scale;  // raw units per m/s^2
  double span = 1;
  for (const auto& f : runs) span = std::max(span, std::abs(f.temperature_c - T0));

  std::vector<TemperatureFit> fits;
  Eigen::VectorXd previous;
  for (int p = min_order; p <= max_order; ++p) {
    const VectorFn residuals = [&, p](const Eigen::VectorXd& th) -> Eigen::VectorXd {
      Eigen::VectorXd res(kTriadParams * static_cast<Eigen::Index>(runs.size()));
      for (std::size_t k = 0; k < runs.size(); ++k)
        res.segment<kTriadParams>(kTriadParams * static_cast<Eigen::Index>(k)) =
            whiten[k] * (predict(th, p, runs[k].temperature_c - T0) - runs[k].fit.params);
      return res;
    };
    Eigen::VectorXd th = Eigen::VectorXd::Zero(size_of(p)), typical(size_of(p));
    if (previous.size() > 0) {
      // Start from the order below: its terms keep their place, the new ones start at zero.
      const int q = p - 1;
      th.head<15>() = previous.head<15>();
      th.segment(15, 3 * q) = previous.segment(15, 3 * q);
      th.segment(15 + 3 * p, 3 * q) = previous.segment(15 + 3 * q, 3 * q);
    } else {
      th.head<15>() = nearest.fit.params;
    }
    typical.head<3>().setConstant(b_scale);
    typical.segment<9>(3).setConstant(s_scale);
    typical.segment<3>(12).setConstant(1e-5);
    // Typical drifts: 1e-3 of full scale (bias) and 1e-2 (scale) over the span, per order.
    for (int q = 1; q <= p; ++q) {
      typical.segment<3>(15 + 3 * (q - 1)).setConstant(1e-3 * b_scale / std::pow(span, q));
      typical.segment<3>(15 + 3 * p + 3 * (q - 1)).setConstant(1e-2 / std::pow(span, q));
    }
    const LmResult lm = levenberg_marquardt(residuals, th, typical,
                                            "the temperature runs do not determine the temperature coefficients of "
                                            "order " + std::to_string(p));
    TemperatureFit f;
    f.order = p;
    f.theta = lm.x;
    f.covariance = lm.covariance;
    f.chi2 = lm.chi2;
    f.dof = lm.dof;
    f.names = names_of(p);
    fits.push_back(f);
    previous = lm.x;
  }
  std::size_t chosen = 0;
  if (order == 0)
    while (chosen + 1 < fits.size() && fits[chosen].chi2 - fits[chosen + 1].chi2 > kChi2Six999) ++chosen;
  TemperatureFit out = fits[chosen];
  for (const auto& f : fits) {
    out.chi2_by_order.push_back(f.chi2);
    out.dof_by_order.push_back(f.dof);
  }
  return out;
}

}  // namespace plumb::calibration::detail
