// `integral`: the source paper's dynamic algorithm (METHODS.md section 1). The sensor products
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

#include "plumb/core/attitude.hpp"
#include "plumb/estimators/demodulation.hpp"
#include "plumb/estimators/platform_angle.hpp"
#include "plumb/estimators/windowed_estimator.hpp"

namespace plumb::estimators {
namespace {

constexpr double kRotatingDeg = 10.0;  // block-mean toolface span above which the platform turns

class IntegralEstimator final : public WindowedEstimator {
 protected:
  estimator::Info describe() const override {
    return {"integral",
            "the paper's dynamic algorithm: products integrated over whole revolutions, small-angle azimuth",
            "1.0.0",
            {},
            false,
            false};
  }

  void configure_plugin(const ParameterReader&) override {}

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

    // Real arithmetic throughout: std::complex products and hypot are several times slower.
    double p1 = 0, p2 = 0, gz = 0, bz = 0, z_re = 0, z_im = 0;
    for (std::size_t k = 0; k < end; ++k) {
      const double gx = w.gx[k], gy = w.gy[k], bx = w.bx[k], by = w.by[k];
      const double cross = gx * by - gy * bx, dot = gx * bx + gy * by;
      p1 += cross;
      p2 += dot;
      // (Gx + iGy)(Bx - iBy) / |Br| = (dot - i cross) / |Br|
      const double radial_b2 = bx * bx + by * by;
      const double inv = radial_b2 > 0 ? 1 / std::sqrt(radial_b2) : 0.0;
      z_re += dot * inv;
      z_im -= cross * inv;
      gz += w.gz[k];
      bz += w.bz[k];
    }
    std::complex<double> z(z_re, z_im);
    const double n = static_cast<double>(end);
    p1 /= n, p2 /= n, gz /= n, bz /= n;
    z /= n;
    const double radial_g = std::abs(z);
    const double total_g = std::hypot(radial_g, gz);
    const double total_b = std::hypot(angle.radial_field, bz);
    e.total_g = total_g;
    e.total_b = total_b;
    if (!(total_g > 0)) {
      e.reason = "zero gravity";
      return e;
    }
    e.valid = true;
    e.inclination_deg = std::atan2(radial_g, gz) / kDeg;
    e.dip_deg = std::asin(std::clamp((p2 + gz * bz) / (total_g * total_b), -1.0, 1.0)) / kDeg;
    const double m_end = angle.phase[w.size() - 1];
    e.magnetic_toolface_deg = wrap_deg_360(m_end / kDeg);

    // Residual spread of the demodulated gravity: its noise, for the standard deviations.
    double ss = 0;
    for (std::size_t k = 0; k < end; ++k) {
      const double gx = w.gx[k], gy = w.gy[k], bx = w.bx[k], by = w.by[k];
      const double radial_b2 = bx * bx + by * by;
      if (!(radial_b2 > 0)) continue;
      const double inv = 1 / std::sqrt(radial_b2);
      const double re = (gx * bx + gy * by) * inv - z.real(), im = -(gx * by - gy * bx) * inv - z.imag();
      ss += re * re + im * im;
    }
    const double sigma = std::sqrt(ss / std::max(1.0, 2 * (n - 1)));
    const double radial_g_sd = sigma / std::sqrt(n);
    e.inclination_sd_deg = radial_g_sd / total_g / kDeg;
    if (!(radial_g > 3 * radial_g_sd && e.inclination_deg > kMinInclinationForToolfaceDeg) || std::hypot(p1, p2) <= 0) {
      e.reason = "near vertical: toolface and azimuth undefined";
      return e;
    }
    e.azimuth_valid = e.toolface_valid = true;
    e.azimuth_deg = wrap_deg_360(std::atan2(p1, -p2) / kDeg);
    const double alpha = -std::arg(-z);  // T - M
    e.gravity_toolface_deg = wrap_deg_360((m_end + alpha) / kDeg);
    e.azimuth_sd_deg = e.toolface_sd_deg = radial_g_sd / radial_g / kDeg;
    return e;
  }
};

}  // namespace
}  // namespace plumb::estimators

PLUMB_ESTIMATOR_PLUGIN(plumb::estimators::IntegralEstimator, "integral",
                       "the paper's dynamic algorithm (whole revolutions, small-angle azimuth)")
