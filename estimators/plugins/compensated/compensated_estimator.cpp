// `compensated`: the integral algorithm without its systematic error (docs/methods.md section 1).
// Instead of the small-angle ratio it evaluates the exact closed form of docs/conventions.md on the
// platform-rotation invariants. With the radial gravity Gx + iGy = c e^{-i phi} and the radial field
// Bx - iBy = d e^{i phi} demodulated against the tracked platform angle phi, the radial field in the
// frame of the gravity high side is (u, v) = |d| (cos alpha, sin alpha), alpha = T - M, and
//   A = atan2(|G| (-v), Bz |c| + Gz u),   I = atan2(|c|, Gz),
// which is the closed form with P1 = -|c| v, P2 = -|c| u, Gx^2 + Gy^2 = |c|^2 (free of the 2 sigma^2
// noise bias that averaging Gx^2 + Gy^2 would carry). Constant radial sensor biases are fitted
// alongside once the window holds a revolution, so it needs no whole number of turns.
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

// (I, A, T - phi_end) from x = (Re c, Im c, Re d, Im d, mean Gz, mean Bz): the closed form on the
// rotation invariants (see the top of this file), exact at any attitude.
Eigen::Vector3d attitude_from_invariants(const Eigen::VectorXd& x) {
  const std::complex<double> c(x[0], x[1]), d(x[2], x[3]);
  const double gz = x[4], bz = x[5];
  const double radial_g = std::abs(c), r = std::abs(d);
  const double alpha = -std::arg(-c) - std::arg(d);
  const double azimuth =
      std::atan2(-std::hypot(radial_g, gz) * r * std::sin(alpha), bz * radial_g + gz * r * std::cos(alpha));
  return {std::atan2(radial_g, gz), azimuth, -std::arg(-c)};
}

class CompensatedEstimator final : public WindowedEstimator {
 protected:
  estimator::Info describe() const override {
    return {"compensated",
            "exact closed form on demodulated rotation invariants: no small-angle error, fits radial sensor biases",
            "1.0.0",
            {{"estimate_biases", "true", "fit constant radial accelerometer and magnetometer biases (needs one revolution)"},
             {"smoothing", "0.1", "half-width in seconds of the platform-angle smoother used when speed is irregular"}}};
  }

  void configure_plugin(const ParameterReader& params) override {
    estimate_biases_ = params.boolean("estimate_biases");
    angle_options_.smoothing_s = params.number("smoothing", 0.0, 10.0);
  }

  Estimate estimate_window(const WindowData& w) override {
    Estimate e;
    const PlatformAngle angle = track_platform_angle(w, angle_options_);
    if (!angle.ok) {
      e.reason = angle.reason;
      return e;
    }
    e.rpm = angle.rpm();
    e.rotating = angle.motion_rad > kRotatingDeg * kDeg;
    angle.phasors(cos_phase_, sin_phase_);
    const Demodulation dm = demodulate(w, angle.phase, cos_phase_, sin_phase_, 0, w.size(), estimate_biases_);
    const double n = static_cast<double>(dm.n);
    e.samples_used = static_cast<std::uint32_t>(dm.n);

    const double radial_g = std::abs(dm.gravity);
    const double r = std::abs(dm.field);
    const double total_g = std::hypot(radial_g, dm.mean_gz);
    const double total_b = std::hypot(r, dm.mean_bz);
    e.total_g = total_g;
    e.total_b = total_b;
    if (!(total_g > 0) || !(total_b > 0)) {
      e.reason = !(total_g > 0) ? "zero gravity" : "zero magnetic field";
      return e;
    }
    e.valid = true;
    e.inclination_deg = std::atan2(radial_g, dm.mean_gz) / kDeg;
    const double gb = std::real(dm.gravity * dm.field) + dm.mean_gz * dm.mean_bz;
    e.dip_deg = std::asin(std::clamp(gb / (total_g * total_b), -1.0, 1.0)) / kDeg;

    const double phi_end = angle.phase.back();
    const double gravity_phase = std::arg(-dm.gravity);  // phi - T
    const double field_phase = std::arg(dm.field);       // M - phi
    e.magnetic_toolface_deg = wrap_deg_360((phi_end + field_phase) / kDeg);

    // Standard deviations: the window's own noise propagated through the formulas
    // above at this attitude. Inputs c, d (per component), mean Gz, mean Bz; their noises are
    // independent (different sensor axes). A common error of the platform angle phi turns c and d
    // oppositely and cancels in alpha, so the field's tangential noise enters alpha as the mean of
    // the raw toolface noise: per axis, the larger of the fit's residual and the toolface noise
    // times r^2 (a smoother absorbs part of the noise into phi and so shrinks the residual).
    const double var_c = dm.gravity_residual_var * dm.coefficient_var_factor;
    const double var_d = std::max(dm.field_residual_var, angle.phase_noise_var * r * r) * dm.coefficient_var_factor;
    Eigen::VectorXd x(6), var(6);
    x << dm.gravity.real(), dm.gravity.imag(), dm.field.real(), dm.field.imag(), dm.mean_gz, dm.mean_bz;
    var << var_c, var_c, var_d, var_d, dm.gz_var / n, dm.bz_var / n;
    const Eigen::Vector3d sd = propagate_attitude_sd_independent(attitude_from_invariants, x, var);
    e.inclination_sd_deg = sd[0] / kDeg;
    // Reported even when the angles are refused below: near vertical they say how bad it is.
    e.azimuth_sd_deg = sd[1] / kDeg;
    // The toolface at the window end also carries the platform angle's error there.
    e.toolface_sd_deg = std::sqrt(sd[2] * sd[2] + angle.end_phase_var) / kDeg;
    const double radial_g_sd = std::sqrt(var_c);
    const bool radial_gravity_seen = radial_g > 3 * radial_g_sd && e.inclination_deg > kMinInclinationForToolfaceDeg;
    if (!radial_gravity_seen) {
      e.reason = "near vertical: toolface and azimuth undefined";
      return e;
    }
    e.toolface_valid = true;
    e.azimuth_valid = true;
    e.gravity_toolface_deg = wrap_deg_360((phi_end - gravity_phase) / kDeg);
    e.azimuth_deg = wrap_deg_360(attitude_from_invariants(x)[1] / kDeg);
    if (std::abs(e.rpm) > 1e-9 && angle.revolutions() < 1 && e.rotating) {
      e.reason = "less than one revolution in window: radial sensor biases not removed";
    }
    return e;
  }

 private:
  bool estimate_biases_ = true;
  PlatformAngleOptions angle_options_;
  std::vector<double> cos_phase_, sin_phase_;  // reused across windows
};

}  // namespace
}  // namespace plumb::windowed

PLUMB_ESTIMATOR_PLUGIN(plumb::windowed::CompensatedEstimator,
                       "exact closed form on demodulated rotation invariants")
