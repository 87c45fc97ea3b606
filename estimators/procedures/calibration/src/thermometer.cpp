#include "plumb/calibration/thermometer.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>
#include <Eigen/QR>

#include "plumb/calibration/types.hpp"

namespace plumb::calibration {

ThermometerFit fit_thermometer(const std::vector<ThermometerPoint>& points, double nonlinear_above_c) {
  if (points.empty()) throw CalibrationError("no reference thermometer readings: the thermometer cannot be calibrated");
  std::vector<double> refs;
  for (const auto& p : points) refs.push_back(p.reference_c);
  std::sort(refs.begin(), refs.end());
  int distinct = 1;
  for (std::size_t i = 1; i < refs.size(); ++i)
    if (refs[i] - refs[i - 1] > 1.0) ++distinct;
  ThermometerFit out;
  out.min_c = refs.front();
  out.max_c = refs.back();
  const bool hot = out.max_c > nonlinear_above_c;
  out.degree = hot && distinct >= 4 ? 3 : std::min(1, distinct - 1);
  const int m = out.degree + 1;
  const auto n = static_cast<Eigen::Index>(points.size());
  if (n <= m) throw CalibrationError("too few thermometer points for a degree " + std::to_string(out.degree) + " fit");

  // Fit in a centred, scaled variable (well conditioned), then expand into powers of t exactly.
  double lo = points[0].raw_c, hi = lo;
  for (const auto& p : points) lo = std::min(lo, p.raw_c), hi = std::max(hi, p.raw_c);
  const double centre = 0.5 * (lo + hi), half = std::max(0.5 * (hi - lo), 1.0);
  Eigen::MatrixXd H(n, m);
  Eigen::VectorXd y(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double x = (points[static_cast<std::size_t>(i)].raw_c - centre) / half;
    double xp = 1;
    for (int k = 0; k < m; ++k) H(i, k) = xp, xp *= x;
    y[i] = points[static_cast<std::size_t>(i)].reference_c;
  }
  const Eigen::VectorXd a = H.colPivHouseholderQr().solve(y);
  const Eigen::VectorXd res = H * a - y;
  out.rms_c = std::sqrt(res.squaredNorm() / static_cast<double>(n));
  const double s2 = res.squaredNorm() / static_cast<double>(n - m);
  const Eigen::MatrixXd cov_a = s2 * (H.transpose() * H).inverse();

  // x^k = ((t - centre) / half)^k expanded: coefficient of t^j is C(k, j) (-centre)^(k-j) / half^k.
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(4, m);
  for (int k = 0; k < m; ++k) {
    double binom = 1;
    for (int j = 0; j <= k; ++j) {
      if (j > 0) binom = binom * (k - j + 1) / j;
      E(j, k) = binom * std::pow(-centre, k - j) / std::pow(half, k);
    }
  }
  const Eigen::Vector4d c = E * a;
  for (int j = 0; j < 4; ++j) out.coefficients[static_cast<std::size_t>(j)] = c[j];
  out.covariance = E * cov_a * E.transpose();
  return out;
}

}  // namespace plumb::calibration
