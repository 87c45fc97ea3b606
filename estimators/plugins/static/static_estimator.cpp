// `static`: the classical closed form of docs/conventions.md on the window means of G = -f and B.
// Exact for a still platform (and then as good as the data allow: the means are sufficient
// statistics of a constant in white noise), meaningless while it turns, since averaging rotating
// radial channels destroys them; so it watches the magnetic toolface and refuses turning windows.
#include <cmath>
#include <cstdio>

#include <Eigen/Core>

#include "plumb/core/attitude.hpp"
#include "plumb/windowed/error_propagation.hpp"
#include "plumb/windowed/platform_angle.hpp"
#include "plumb/windowed/windowed_estimator.hpp"

namespace plumb::windowed {
namespace {

// (I, A, T) in radians from x = (mean G, mean B): the closed form of docs/conventions.md, as
// closed_form_attitude computes it but without its near-vertical cut-off (differentiated here).
Eigen::Vector3d closed_form_radians(const Eigen::VectorXd& x) {
  const double gx = x[0], gy = x[1], gz = x[2], bx = x[3], by = x[4], bz = x[5];
  const double radial2 = gx * gx + gy * gy;
  const double total_g = std::sqrt(radial2 + gz * gz);
  return {std::atan2(std::sqrt(radial2), gz), std::atan2(total_g * (gx * by - gy * bx), bz * radial2 - gz * (gx * bx + gy * by)),
          std::atan2(gy, -gx)};
}

class StaticEstimator final : public WindowedEstimator {
 protected:
  estimator::Info describe() const override {
    return {"static",
            "classical closed-form attitude on window means; invalid while the platform turns",
            "1.0.0",
            {{"max_turn", "10", "degrees of magnetic toolface turn in a window above which the platform is rotating"}}};
  }

  void configure_plugin(const ParameterReader& params) override { max_turn_deg_ = params.number("max_turn", 0.0, 360.0); }

  Estimate estimate_window(const WindowData& w) override {
    const std::size_t count = w.size();
    const double n = static_cast<double>(count);
    Eigen::Vector3d g = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < count; ++k) {
      g += Eigen::Vector3d(w.gx[k], w.gy[k], w.gz[k]);
      b += Eigen::Vector3d(w.bx[k], w.by[k], w.bz[k]);
    }
    g /= n;
    b /= n;
    // Per-axis sample variances: the noise of each mean is var / n.
    Eigen::Vector3d var_g = Eigen::Vector3d::Zero(), var_b = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < count; ++k) {
      var_g += (Eigen::Vector3d(w.gx[k], w.gy[k], w.gz[k]) - g).cwiseAbs2();
      var_b += (Eigen::Vector3d(w.bx[k], w.by[k], w.bz[k]) - b).cwiseAbs2();
    }
    var_g /= n - 1;
    var_b /= n - 1;
    const ClosedForm cf = closed_form_attitude(g, b);
    Estimate e;
    e.samples_used = static_cast<std::uint32_t>(count);
    e.inclination_deg = cf.inclination_deg;
    e.azimuth_deg = cf.azimuth_deg;
    e.gravity_toolface_deg = cf.gravity_toolface_deg;
    e.magnetic_toolface_deg = cf.magnetic_toolface_deg;
    e.dip_deg = cf.dip_deg;
    e.total_g = cf.total_g;
    e.total_b = cf.total_b;
    e.valid = cf.valid;
    e.azimuth_valid = cf.azimuth_valid;
    e.toolface_valid = cf.toolface_valid;
    e.reason = cf.reason;

    // Standard deviations: the means' noise propagated through the closed form itself
    // at this attitude (its Jacobian by central differences), for inclination, azimuth and toolface.
    if (cf.valid) {
      Eigen::VectorXd x(6), var(6);
      x << g, b;
      var << var_g / n, var_b / n;
      const Eigen::Vector3d sd = propagate_attitude_sd_independent(closed_form_radians, x, var);
      e.inclination_sd_deg = sd[0] / kDeg;
      e.azimuth_sd_deg = sd[1] / kDeg;
      e.toolface_sd_deg = sd[2] / kDeg;
    }

    const PlatformAngle angle = track_platform_angle(w, {0.1, 1});
    if (angle.ok) {
      e.rpm = angle.rpm();
      const double turn_deg = angle.motion_rad / kDeg;
      e.rotating = turn_deg > max_turn_deg_;
      if (e.rotating) {
        char text[96];
        std::snprintf(text, sizeof text, "platform rotating (%.0f deg of turn in window)", turn_deg);
        e.valid = e.azimuth_valid = e.toolface_valid = false;
        // Means of turning radial channels are meaningless, and so would be their sigmas: 0 = unknown.
        e.inclination_sd_deg = e.azimuth_sd_deg = e.toolface_sd_deg = 0;
        e.reason = text;
      }
    }
    return e;
  }

 private:
  double max_turn_deg_ = 10;
};

}  // namespace
}  // namespace plumb::windowed

PLUMB_ESTIMATOR_PLUGIN(plumb::windowed::StaticEstimator,
                       "classical closed-form attitude on window means (platform still)")
