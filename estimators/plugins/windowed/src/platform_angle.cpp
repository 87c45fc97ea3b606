#include "plumb/windowed/platform_angle.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "plumb/core/attitude.hpp"
#include "plumb/windowed/fast_math.hpp"

namespace plumb::windowed {

double PlatformAngle::rpm() const { return rate_rad_s * 60.0 / (2 * kPi); }
double PlatformAngle::revolutions() const { return std::abs(turn_rad) / (2 * kPi); }

void PlatformAngle::phasors(std::vector<double>& cos_phase, std::vector<double>& sin_phase) const {
  const std::size_t n = phase.size();
  cos_phase.resize(n);
  sin_phase.resize(n);
  if (!uniform_linear) {
    for (std::size_t k = 0; k < n; ++k) cos_phase[k] = std::cos(phase[k]), sin_phase[k] = std::sin(phase[k]);
    return;
  }
  const double cs = std::cos(step), sn = std::sin(step);
  double c = 0, s = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (k % 1024 == 0) {
      // Restart from the exact value now and then so rounding cannot accumulate.
      c = std::cos(phase[k]), s = std::sin(phase[k]);
    } else {
      const double next_c = c * cs - s * sn;
      s = s * cs + c * sn;
      c = next_c;
    }
    cos_phase[k] = c;
    sin_phase[k] = s;
  }
}

double noise_variance_from_second_differences(const std::vector<double>& y) {
  if (y.size() < 3) return 0;
  double sum = 0;
  for (std::size_t k = 2; k < y.size(); ++k) {
    const double d2 = y[k] - 2 * y[k - 1] + y[k - 2];
    sum += d2 * d2;
  }
  return sum / (6.0 * static_cast<double>(y.size() - 2));
}

std::vector<double> smooth_local_quadratic(const std::vector<double>& y, int half_width) {
  const int n = static_cast<int>(y.size());
  std::vector<double> out(y);
  if (n < 3 || half_width < 1) return out;
  const int m = std::min(half_width, (n - 1) / 2);
  // Interior: Savitzky-Golay quadratic weights at the centre of 2m+1 points.
  std::vector<double> weight(2 * m + 1);
  const double mm = m;
  const double norm = (2 * mm - 1) * (2 * mm + 1) * (2 * mm + 3);
  for (int j = -m; j <= m; ++j) weight[j + m] = (3 * (3 * mm * mm + 3 * mm - 1) - 15.0 * j * j) / norm;
  for (int k = m; k < n - m; ++k) {
    double s = 0;
    for (int j = -m; j <= m; ++j) s += weight[j + m] * y[k + j];
    out[k] = s;
  }
  // Ends: one quadratic fitted to the first (last) 2m+1 points, evaluated where needed.
  auto fit_edge = [&](int first, int from, int to) {
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (int k = first; k < first + 2 * m + 1; ++k) {
      const double x = (k - first - mm) / std::max(mm, 1.0);
      const Eigen::Vector3d p(1, x, x * x);
      a += p * p.transpose();
      b += p * y[k];
    }
    const Eigen::Vector3d c = a.ldlt().solve(b);
    for (int k = from; k < to; ++k) {
      const double x = (k - first - mm) / std::max(mm, 1.0);
      out[k] = c[0] + c[1] * x + c[2] * x * x;
    }
  };
  fit_edge(0, 0, m);
  fit_edge(n - 2 * m - 1, n - m, n);
  return out;
}

namespace {

// Least-squares polynomial of the given degree in normalised time; returns coefficients.
struct PolyFit {
  Eigen::VectorXd coef;
  double residual_var = 0;
};

PolyFit fit_polynomial(const std::vector<double>& tau, const std::vector<double>& y, int degree) {
  const int p = degree + 1;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(p, p);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(p);
  double pw[8];
  for (std::size_t k = 0; k < tau.size(); ++k) {
    pw[0] = 1;
    for (int j = 1; j < p; ++j) pw[j] = pw[j - 1] * tau[k];
    for (int i = 0; i < p; ++i) {
      b[i] += pw[i] * y[k];
      for (int j = 0; j <= i; ++j) a(i, j) += pw[i] * pw[j];
    }
  }
  a = a.selfadjointView<Eigen::Lower>();
  PolyFit fit;
  fit.coef = a.ldlt().solve(b);
  double ss = 0;
  for (std::size_t k = 0; k < tau.size(); ++k) {
    double v = 0;
    for (int j = p - 1; j >= 0; --j) v = v * tau[k] + fit.coef[j];
    ss += (y[k] - v) * (y[k] - v);
  }
  const double dof = static_cast<double>(tau.size()) - p;
  fit.residual_var = dof > 0 ? ss / dof : 0;
  return fit;
}

// The straight line in closed form from its sums: the common case of constant speed.
PolyFit line_from_sums(double s0, double s1, double s2, double sy, double sty, double syy) {
  PolyFit fit;
  fit.coef = Eigen::Vector2d::Zero();
  const double det = s0 * s2 - s1 * s1;
  if (!(det > 0)) return fit;
  fit.coef[0] = (s2 * sy - s1 * sty) / det;
  fit.coef[1] = (s0 * sty - s1 * sy) / det;
  const double ss = syy - fit.coef[0] * sy - fit.coef[1] * sty;
  fit.residual_var = s0 > 2 ? std::max(0.0, ss) / (s0 - 2) : 0;
  return fit;
}

double block_span(const std::vector<double>& t, const std::vector<double>& angle) {
  // Means over half-second blocks (at least 5 samples): their spread tells turning from noise.
  const std::size_t n = t.size();
  const double span_s = t.back() - t.front();
  const std::size_t per_block =
      std::max<std::size_t>(5, static_cast<std::size_t>(0.5 * static_cast<double>(n) / std::max(span_s, 1e-9)));
  double lo = 1e300, hi = -1e300;
  for (std::size_t start = 0; start < n; start += per_block) {
    const std::size_t end = std::min(n, start + per_block);
    if (end - start < 3 && start != 0) break;
    double s = 0;
    for (std::size_t k = start; k < end; ++k) s += angle[k];
    const double mean = s / static_cast<double>(end - start);
    lo = std::min(lo, mean);
    hi = std::max(hi, mean);
  }
  return hi - lo;
}

// The local quadratic's error at the last sample (rad^2): its noise (the endpoint leverage h2 of a
// quadratic over the last 2m+1 points, about 9/(2m+1)) plus its model error where the speed changes
// fast (stick-slip: the angle's third derivative, which a quadratic cannot follow). The model error
// is estimated by the cubic's endpoint less the quadratic's, whose noise variance (h3 - h2) sigma^2
// is subtracted from its square: an unbiased estimate, zero on average when a quadratic suffices.
double smoother_end_error_var(const std::vector<double>& raw, int m, double noise_var) {
  const int n = static_cast<int>(raw.size());
  const int points = 2 * m + 1;
  if (m < 2 || points > n) return noise_var;
  Eigen::MatrixXd x(points, 4);
  Eigen::VectorXd y(points);
  for (int k = 0; k < points; ++k) {
    const double t = static_cast<double>(k - m) / m;  // -1 .. 1, the last sample at +1
    x.row(k) << 1, t, t * t, t * t * t;
    y[k] = raw[static_cast<std::size_t>(n - points + k)] - raw[static_cast<std::size_t>(n - 1)];
  }
  const Eigen::Vector4d end(1, 1, 1, 1);
  const Eigen::MatrixXd x2 = x.leftCols(3);
  const Eigen::Matrix3d inv2 = (x2.transpose() * x2).inverse();
  const Eigen::Matrix4d inv3 = (x.transpose() * x).inverse();
  const double h2 = end.head<3>().dot(inv2 * end.head<3>()), h3 = end.dot(inv3 * end);
  const double quadratic_end = end.head<3>().dot(inv2 * (x2.transpose() * y));
  const double cubic_end = end.dot(inv3 * (x.transpose() * y));
  const double diff = cubic_end - quadratic_end;
  return h2 * noise_var + std::max(0.0, diff * diff - (h3 - h2) * noise_var);
}

// The window's time axis, normalised: tau = (t - t_mid) / half in [-1, 1].
struct TimeAxis {
  double t0, t_mid, half, inv_half, even_dt;
};

// The toolface of every sample, unwrapped into pa.raw; returns the mean square radial field.
// Two light loops rather than one heavy one: a single loop holds more live values than there are
// registers, and a spilled accumulator puts a memory round trip into every iteration.
double unwrap_toolface(const WindowData& w, PlatformAngle& pa) {
  const std::size_t n = w.size();
  pa.raw.resize(n);
  double radial_sum = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double bx = w.bx[k], by = w.by[k];
    radial_sum += bx * bx + by * by;
    pa.raw[k] = fast_atan2(-by, bx);
  }
  double previous = pa.raw[0];
  double offset = 0;  // multiple of 2 pi added so far
  for (std::size_t k = 1; k < n; ++k) {
    const double m = pa.raw[k];
    const double d = m - previous;
    offset -= d > kPi ? 2 * kPi : 0.0;
    offset += d < -kPi ? 2 * kPi : 0.0;
    previous = m;
    pa.raw[k] = m + offset;
  }
  return radial_sum / static_cast<double>(n);
}

// What the constant-speed case needs from the unwrapped toolface y = raw - origin: its second
// differences (the phase noise) and the straight-line sums in tau.
struct LineSums {
  double d2_sum = 0, s1 = 0, s2 = 0, sy = 0, sty = 0, syy = 0;
};

LineSums line_sums(const WindowData& w, const std::vector<double>& raw, const TimeAxis& axis) {
  LineSums s;
  const double origin = raw[0];
  double last = origin, before_last = origin;
  for (std::size_t k = 0; k < raw.size(); ++k) {
    const double unwrapped = raw[k];
    if (k >= 2) {
      const double d2 = unwrapped - 2 * last + before_last;
      s.d2_sum += d2 * d2;
    }
    before_last = last;
    last = unwrapped;
    const double tau = (w.t[k] - axis.t_mid) * axis.inv_half, y = unwrapped - origin;
    s.s1 += tau, s.s2 += tau * tau, s.sy += y, s.sty += tau * y, s.syy += y * y;
  }
  return s;
}

// The largest distance of a sample time from an even grid: whether the step can be used.
double worst_spacing(const WindowData& w, const TimeAxis& axis) {
  double worst = 0;
  for (std::size_t k = 0; k < w.size(); ++k)
    worst = std::max(worst, std::abs(w.t[k] - axis.t0 - axis.even_dt * static_cast<double>(k)));
  return worst;
}

// The lowest polynomial degree whose residuals are the noise alone (3 sigma of the variance
// estimate), evaluated into pa.phase; pa.model_degree stays 0 when none up to max_degree fits.
void fit_phase_polynomial(const WindowData& w, const TimeAxis& axis, const PolyFit& linear, int max_degree,
                          PlatformAngle& pa) {
  const std::size_t n = w.size();
  const double origin = pa.raw[0];
  const double tolerance = pa.phase_noise_var * (1 + 6 * std::sqrt(2.0 / static_cast<double>(n))) + 1e-12;
  std::vector<double> tau, y;  // built only when a curve is needed
  for (int degree = 1; degree <= max_degree; ++degree) {
    if (degree == 2) {
      tau.resize(n), y.resize(n);
      for (std::size_t k = 0; k < n; ++k) tau[k] = (w.t[k] - axis.t_mid) * axis.inv_half, y[k] = pa.raw[k] - origin;
    }
    const PolyFit fit = degree == 1 ? linear : fit_polynomial(tau, y, degree);
    if (fit.residual_var > tolerance) continue;
    pa.model_degree = degree;
    pa.residual_var = fit.residual_var;
    pa.phase.resize(n);
    pa.end_phase_var = pa.phase_noise_var * ((degree + 1) * (degree + 1) - 1) / static_cast<double>(n);
    if (degree == 1) {
      const double a = origin + fit.coef[0], b = fit.coef[1] * axis.inv_half;
      for (std::size_t k = 0; k < n; ++k) pa.phase[k] = a + b * (w.t[k] - axis.t_mid);
      return;
    }
    for (std::size_t k = 0; k < n; ++k) {
      const double x = (w.t[k] - axis.t_mid) * axis.inv_half;
      double v = 0;
      for (int j = degree; j >= 0; --j) v = v * x + fit.coef[j];
      pa.phase[k] = v + origin;
    }
    return;
  }
}

// No polynomial fits (stick-slip): a local quadratic smoother, and its error at the last sample.
void smooth_phase(const WindowData& w, double smoothing_s, PlatformAngle& pa) {
  const std::size_t n = w.size();
  const double dt = w.nominal_dt > 0 ? w.nominal_dt : (w.t.back() - w.t.front()) / static_cast<double>(n - 1);
  const int half_width = std::max(2, static_cast<int>(std::lround(smoothing_s / std::max(dt, 1e-9))));
  pa.phase = smooth_local_quadratic(pa.raw, half_width);
  pa.end_phase_var = smoother_end_error_var(pa.raw, std::min(half_width, static_cast<int>(n - 1) / 2), pa.phase_noise_var);
  double ss = 0;
  for (std::size_t k = 0; k < n; ++k) ss += (pa.raw[k] - pa.phase[k]) * (pa.raw[k] - pa.phase[k]);
  pa.residual_var = ss / static_cast<double>(n);
}

}  // namespace

PlatformAngle track_platform_angle(const WindowData& w, const PlatformAngleOptions& options) {
  PlatformAngle pa;
  const std::size_t n = w.size();
  if (n < 3) {
    pa.reason = "too few samples to track the platform angle";
    return pa;
  }
  // Everything the constant-speed case needs in light passes (this is the estimators' hot loop):
  // the unwrapped toolface, its second differences, the straight-line sums in normalised time
  // tau in [-1, 1], and whether the samples are evenly spaced.
  TimeAxis axis;
  axis.t0 = w.t.front();
  axis.t_mid = 0.5 * (axis.t0 + w.t.back());
  axis.half = std::max(0.5 * (w.t.back() - axis.t0), 1e-9);
  axis.inv_half = 1 / axis.half;
  axis.even_dt = (w.t.back() - axis.t0) / static_cast<double>(n - 1);
  const double mean_square_radial = unwrap_toolface(w, pa);
  const LineSums sums = line_sums(w, pa.raw, axis);
  const double spacing = worst_spacing(w, axis);
  pa.radial_field = std::sqrt(mean_square_radial);  // RMS: no per-sample square root
  pa.phase_noise_var = sums.d2_sum / (6.0 * static_cast<double>(n - 2));
  pa.block_span_rad = block_span(w.t, pa.raw);
  if (!(pa.radial_field > 0)) {
    pa.reason = "no radial magnetic field: platform angle unknown";
    return pa;
  }
  // Phase noise near a radian means the toolface cannot be unwrapped reliably.
  if (pa.phase_noise_var > 0.5 * 0.5) {
    pa.reason = "radial magnetic field too weak against its noise to track the platform angle";
    return pa;
  }

  const PolyFit linear = line_from_sums(static_cast<double>(n), sums.s1, sums.s2, sums.sy, sums.sty, sums.syy);
  pa.rate_rad_s = linear.coef[1] / axis.half;
  // Block means miss the turn of a short window (one block); the fitted line does not.
  pa.motion_rad = std::max(pa.block_span_rad, std::abs(pa.rate_rad_s) * 2 * axis.half);
  fit_phase_polynomial(w, axis, linear, options.max_degree, pa);
  if (pa.model_degree == 0) smooth_phase(w, options.smoothing_s, pa);
  if (pa.model_degree == 1) {
    pa.uniform_linear = spacing <= 1e-6 * axis.even_dt;
    pa.step = pa.rate_rad_s * axis.even_dt;
  }
  pa.turn_rad = pa.phase.back() - pa.phase.front();
  pa.ok = true;
  return pa;
}

}  // namespace plumb::windowed
