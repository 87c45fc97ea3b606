// `compensated`: the integral algorithm without its systematic error (METHODS.md section 1).
// Instead of the small-angle ratio it evaluates the exact closed form of CONVENTIONS.md on the
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

#include "plumb/core/attitude.hpp"
#include "plumb/estimators/demodulation.hpp"
#include "plumb/estimators/platform_angle.hpp"
#include "plumb/estimators/windowed_estimator.hpp"

namespace plumb::estimators {
namespace {

constexpr double kRotatingDeg = 10.0;  // block-mean toolface span above which the platform turns

class CompensatedEstimator final : public WindowedEstimator {
 protected:
  estimator::Info describe() const override {
    return {"compensated",
            "exact closed form on demodulated rotation invariants: no small-angle error, fits radial sensor biases",
            "1.0.0",
            {{"estimate_biases", "true", "fit constant radial accelerometer and magnetometer biases (needs one revolution)"},
             {"smoothing", "0.1", "half-width in seconds of the platform-angle smoother used when speed is irregular"}},
            false,
            false};
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

    const double sigma_a = std::sqrt(dm.gravity_residual_var);
    const double radial_g_sd = sigma_a / std::sqrt(n);
    e.inclination_sd_deg = radial_g_sd / total_g / kDeg;
    const bool radial_gravity_seen = radial_g > 3 * radial_g_sd && e.inclination_deg > kMinInclinationForToolfaceDeg;
    if (!radial_gravity_seen) {
      e.reason = "near vertical: toolface and azimuth undefined";
      return e;
    }
    e.toolface_valid = true;
    e.azimuth_valid = true;
    e.gravity_toolface_deg = wrap_deg_360((phi_end - gravity_phase) / kDeg);
    const double alpha = -gravity_phase - field_phase;
    auto azimuth = [&](double a) {
      return std::atan2(-total_g * r * std::sin(a), dm.mean_bz * radial_g + dm.mean_gz * r * std::cos(a));
    };
    e.azimuth_deg = wrap_deg_360(azimuth(alpha) / kDeg);
    // alpha's variance: the gravity phase (tangential noise over |c|) plus the platform angle's.
    const double phase_var = dm.gravity_residual_var / (n * radial_g * radial_g) + angle.phase_noise_var / n;
    const double h = 1e-4;
    const double slope = wrap_deg_180((azimuth(alpha + h) - azimuth(alpha - h)) / kDeg) * kDeg / (2 * h);
    e.azimuth_sd_deg = std::abs(slope) * std::sqrt(phase_var) / kDeg;
    e.toolface_sd_deg = std::sqrt(phase_var) / kDeg;
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
}  // namespace plumb::estimators

PLUMB_ESTIMATOR_PLUGIN(plumb::estimators::CompensatedEstimator, "compensated",
                       "exact closed form on demodulated rotation invariants")
