// `integral`: the source paper's dynamic algorithm (docs/methods.md section 1). The sensor products
// P1 = Gx By - Gy Bx and P2 = Gx Bx + Gy By are integrated over the largest whole number of platform
// revolutions in the window (which also cancels constant radial sensor biases) and the azimuth
// comes from their ratio in the small-angle form A' = atan2(P1, -P2). Since P1 = g sinI Bh sinA
// and -P2 = g sinI (cosI Bh cosA - sinI Bv), A' errs by about sinI tan(dip) sinA: the paper's
// finding, an error growing with inclination and largest at 90 and 270 degrees of azimuth.
// The inclination comes from demodulating the radial gravity against the magnetic toolface,
// (Gx + iGy)(Bx - iBy)/|Br| = -g sinI e^{-i alpha}, a constant at any speed profile.
#include <cmath>
#include <complex>
#include <cstdio>

#include <Eigen/Core>

#include "plumb/core/attitude.hpp"
#include "plumb/windowed/demodulation.hpp"
#include "plumb/windowed/error_propagation.hpp"
#include "plumb/windowed/platform_angle.hpp"
#include "plumb/windowed/windowed_estimator.hpp"

namespace plumb::windowed {
namespace {

constexpr double kRotatingDeg = 10.0;  // block-mean toolface span above which the platform turns

// (I, -, T - M_end) from x = (Re z, Im z, mean Gz).
Eigen::Vector3d inclination_and_toolface(const Eigen::VectorXd& x) {
  const std::complex<double> z(x[0], x[1]);
  return {std::atan2(std::abs(z), x[2]), 0.0, -std::arg(-z)};
}

// (-, A', -) from x = (P1, P2): the paper's small-angle azimuth.
Eigen::Vector3d small_angle_azimuth(const Eigen::VectorXd& x) { return {0.0, std::atan2(x[0], -x[1]), 0.0}; }

// The small-angle azimuth's own error A' - A = atan2(Bh sinA, cosI Bh cosA - sinI Bv) - A at an
// inclination and dip (radians): its RMS and largest value over azimuth (72 azimuths: the error is
// smooth in A).
struct SmallAngleError {
  double rms = 0, max = 0;
};
SmallAngleError small_angle_error(double inc, double dip) {
  SmallAngleError out;
  constexpr int kSteps = 72;
  for (int k = 0; k < kSteps; ++k) {
    const double a = 2 * kPi * k / kSteps;
    const double err = std::remainder(
        std::atan2(std::cos(dip) * std::sin(a), std::cos(inc) * std::cos(dip) * std::cos(a) - std::sin(inc) * std::sin(dip)) - a,
        2 * kPi);
    out.rms += err * err / kSteps;
    out.max = std::max(out.max, std::abs(err));
  }
  out.rms = std::sqrt(out.rms);
  return out;
}

// The means over the whole revolutions: the products P1, P2, the demodulated radial gravity z,
// the axial gravity and field, and the products' and Gz's second moments (sums, for the spreads).
struct RevolutionMeans {
  double p1 = 0, p2 = 0, gz = 0, bz = 0;
  double p11 = 0, p22 = 0, p12 = 0, gz2 = 0;
  std::complex<double> z;
  double n = 0;
};

RevolutionMeans revolution_means(const WindowData& w, std::size_t end) {
  // Real arithmetic throughout: std::complex products and hypot are several times slower.
  RevolutionMeans m;
  double z_re = 0, z_im = 0;
  for (std::size_t k = 0; k < end; ++k) {
    const double gx = w.gx[k], gy = w.gy[k], bx = w.bx[k], by = w.by[k];
    const double cross = gx * by - gy * bx, dot = gx * bx + gy * by;
    m.p1 += cross;
    m.p2 += dot;
    m.p11 += cross * cross, m.p22 += dot * dot, m.p12 += cross * dot;
    // (Gx + iGy)(Bx - iBy) / |Br| = (dot - i cross) / |Br|
    const double radial_b2 = bx * bx + by * by;
    const double inv = radial_b2 > 0 ? 1 / std::sqrt(radial_b2) : 0.0;
    z_re += dot * inv;
    z_im -= cross * inv;
    m.gz += w.gz[k];
    m.gz2 += w.gz[k] * w.gz[k];
    m.bz += w.bz[k];
  }
  m.z = std::complex<double>(z_re, z_im);
  m.n = static_cast<double>(end);
  m.p1 /= m.n, m.p2 /= m.n, m.gz /= m.n, m.bz /= m.n;
  m.z /= m.n;
  return m;
}

// Residual spread of the demodulated gravity (variances of the mean), split along z (its length:
// the inclination) and across it (its phase: the toolface). The field's phase noise shows only
// across z (a turn), so the two differ at large inclinations, where |z| is large.
struct DemodulationSpread {
  std::complex<double> along;
  double var_along = 0, var_across = 0;
};

DemodulationSpread demodulation_spread(const WindowData& w, std::size_t end, const RevolutionMeans& m) {
  const std::complex<double> z = m.z;
  DemodulationSpread s;
  s.along = std::abs(z) > 0 ? z / std::abs(z) : std::complex<double>(1, 0);
  double ss_along = 0, ss_across = 0;
  for (std::size_t k = 0; k < end; ++k) {
    const double gx = w.gx[k], gy = w.gy[k], bx = w.bx[k], by = w.by[k];
    const double radial_b2 = bx * bx + by * by;
    if (!(radial_b2 > 0)) continue;
    const double inv = 1 / std::sqrt(radial_b2);
    const std::complex<double> res((gx * bx + gy * by) * inv - z.real(), -(gx * by - gy * bx) * inv - z.imag());
    const std::complex<double> turned = res * std::conj(s.along);
    ss_along += turned.real() * turned.real();
    ss_across += turned.imag() * turned.imag();
  }
  const double dof = std::max(1.0, m.n - 1);
  s.var_along = ss_along / dof / m.n;
  s.var_across = ss_across / dof / m.n;
  return s;
}

// Standard deviations: the window's noise propagated through the formulas used. Inclination and
// toolface from (z, mean Gz); the per-sample products are constant but for noise, so their sample
// covariance over n gives that of P1, P2 for the azimuth. The small-angle error is a sinusoid of
// azimuth of known amplitude at this inclination and dip: its RMS over azimuth joins the noise (the
// plugin keeps the paper's uncorrected azimuth).
void attach_standard_deviations(const RevolutionMeans& m, const DemodulationSpread& s, const PlatformAngle& angle,
                                const SmallAngleError& model, Estimate& e) {
  const std::complex<double> z = m.z;
  const double n = m.n, dof = std::max(1.0, n - 1);
  const double var_gz = std::max(0.0, m.gz2 - n * m.gz * m.gz) / dof;
  const Eigen::Vector2d u(s.along.real(), s.along.imag()), t(-s.along.imag(), s.along.real());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  cov.topLeftCorner<2, 2>() = s.var_along * u * u.transpose() + s.var_across * t * t.transpose();
  cov(2, 2) = var_gz / n;
  const Eigen::Vector3d sd_gravity =
      propagate_attitude_sd(inclination_and_toolface, Eigen::Vector3d(z.real(), z.imag(), m.gz), Eigen::MatrixXd(cov));
  // Demodulating against the raw, noisy field phase shrinks |z| on average by the factor
  // E[cos eps] = exp(-var_eps / 2): a bias of the paper's inclination, which its sd carries.
  const double shrink = std::abs(z) * (std::exp(0.5 * angle.phase_noise_var) - 1);
  const double inclination_bias = std::abs(inclination_and_toolface(Eigen::Vector3d(z.real(), z.imag(), m.gz))[0] -
                                           inclination_and_toolface(Eigen::Vector3d(z.real() + shrink * u[0],
                                                                                    z.imag() + shrink * u[1], m.gz))[0]);
  e.inclination_sd_deg = std::hypot(sd_gravity[0], inclination_bias) / kDeg;
  Eigen::Matrix2d products;
  products << m.p11 / n - m.p1 * m.p1, m.p12 / n - m.p1 * m.p2, m.p12 / n - m.p1 * m.p2, m.p22 / n - m.p2 * m.p2;
  products /= dof;  // the sample covariance over n: that of the means
  const Eigen::Vector3d sd_azimuth =
      propagate_attitude_sd(small_angle_azimuth, Eigen::Vector2d(m.p1, m.p2), Eigen::MatrixXd(products));
  e.azimuth_sd_deg = std::hypot(sd_azimuth[1], model.rms) / kDeg;
  e.toolface_sd_deg = std::sqrt(sd_gravity[2] * sd_gravity[2] + angle.end_phase_var) / kDeg;
}

class IntegralEstimator final : public WindowedEstimator {
 protected:
  estimator::Info describe() const override {
    return {"integral",
            "the paper's dynamic algorithm: products integrated over whole revolutions, small-angle azimuth",
            "1.0.0",
            {{"max_model_error_deg", "2.5",
              "azimuth flagged invalid where the small-angle error (up to about sinI tan(dip)) can exceed this (deg)"}}};
  }

  void configure_plugin(const ParameterReader& params) override {
    max_model_error_deg_ = params.number("max_model_error_deg", 0.0, 180.0);
  }

  Estimate estimate_window(const WindowData& w) override {
    Estimate e;
    const PlatformAngle angle = track_platform_angle(w);
    if (!angle.ok) {
      e.reason = angle.reason;
      return e;
    }
    e.rpm = angle.rpm();
    e.rotating = angle.motion_rad > kRotatingDeg * kDeg;
    int revolutions = 0;
    const std::size_t end = e.rotating ? whole_revolutions_end(angle.phase, 0, &revolutions) : w.size();
    if (e.rotating && revolutions < 1) {
      char text[128];
      std::snprintf(text, sizeof text, "window too short for a revolution (%.0f deg of turn)",
                    std::abs(angle.turn_rad) / kDeg);
      e.reason = text;
      return e;
    }
    e.samples_used = static_cast<std::uint32_t>(end);

    const RevolutionMeans m = revolution_means(w, end);
    const double radial_g = std::abs(m.z);
    const double total_g = std::hypot(radial_g, m.gz);
    const double total_b = std::hypot(angle.radial_field, m.bz);
    e.total_g = total_g;
    e.total_b = total_b;
    if (!(total_g > 0)) {
      e.reason = "zero gravity";
      return e;
    }
    e.valid = true;
    e.inclination_deg = std::atan2(radial_g, m.gz) / kDeg;
    e.dip_deg = std::asin(std::clamp((m.p2 + m.gz * m.bz) / (total_g * total_b), -1.0, 1.0)) / kDeg;
    const double m_end = angle.phase[w.size() - 1];
    e.magnetic_toolface_deg = wrap_deg_360(m_end / kDeg);

    const DemodulationSpread spread = demodulation_spread(w, end, m);
    const double radial_g_sd = std::sqrt(0.5 * (spread.var_along + spread.var_across));
    const SmallAngleError model = small_angle_error(e.inclination_deg * kDeg, e.dip_deg * kDeg);
    attach_standard_deviations(m, spread, angle, model, e);
    if (!(radial_g > 3 * radial_g_sd && e.inclination_deg > kMinInclinationForToolfaceDeg) || std::hypot(m.p1, m.p2) <= 0) {
      e.reason = "near vertical: toolface and azimuth undefined";
      return e;
    }
    e.azimuth_valid = e.toolface_valid = true;
    e.azimuth_deg = wrap_deg_360(std::atan2(m.p1, -m.p2) / kDeg);
    const double alpha = -std::arg(-m.z);  // T - M
    e.gravity_toolface_deg = wrap_deg_360((m_end + alpha) / kDeg);
    if (model.max / kDeg > max_model_error_deg_) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "small-angle azimuth error up to %.3g deg at this inclination exceeds max_model_error_deg %.3g",
                    model.max / kDeg, max_model_error_deg_);
      e.reason = text;
      e.azimuth_valid = false;
    }
    return e;
  }

 private:
  double max_model_error_deg_ = 2.5;
};

}  // namespace
}  // namespace plumb::windowed

PLUMB_ESTIMATOR_PLUGIN(plumb::windowed::IntegralEstimator,
                       "the paper's dynamic algorithm (whole revolutions, small-angle azimuth)")
