// `static`: the classical closed form of CONVENTIONS.md on the window means of G = -f and B.
// Exact for a still platform (and then as good as the data allow: the means are sufficient
// statistics of a constant in white noise), meaningless while it turns, since averaging rotating
// radial channels destroys them; so it watches the magnetic toolface and refuses turning windows.
#include <cmath>
#include <cstdio>

#include <Eigen/Core>

#include "plumb/core/attitude.hpp"
#include "plumb/estimators/platform_angle.hpp"
#include "plumb/estimators/windowed_estimator.hpp"

namespace plumb::estimators {
namespace {

class StaticEstimator final : public WindowedEstimator {
 protected:
  estimator::Info describe() const override {
    return {"static",
            "classical closed-form attitude on window means; invalid while the platform turns",
            "1.0.0",
            {{"max_turn", "10", "degrees of magnetic toolface turn in a window above which the platform is rotating"}},
            false,
            false};
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
    double var_g = 0, var_b = 0;
    for (std::size_t k = 0; k < count; ++k) {
      var_g += (Eigen::Vector3d(w.gx[k], w.gy[k], w.gz[k]) - g).squaredNorm();
      var_b += (Eigen::Vector3d(w.bx[k], w.by[k], w.bz[k]) - b).squaredNorm();
    }
    var_g /= 3 * (n - 1);
    var_b /= 3 * (n - 1);

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

    const double radial_g = std::hypot(g.x(), g.y()), radial_b = std::hypot(b.x(), b.y());
    if (cf.total_g > 0) e.inclination_sd_deg = std::sqrt(var_g / n) / cf.total_g / kDeg;
    if (radial_g > 0 && radial_b > 0) {
      const double phase_var = var_g / (n * radial_g * radial_g) + var_b / (n * radial_b * radial_b);
      e.azimuth_sd_deg = e.toolface_sd_deg = std::sqrt(phase_var) / kDeg;
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
        e.reason = text;
      }
    }
    return e;
  }

 private:
  double max_turn_deg_ = 10;
};

}  // namespace
}  // namespace plumb::estimators

PLUMB_ESTIMATOR_PLUGIN(plumb::estimators::StaticEstimator, "static",
                       "classical closed-form attitude on window means (platform still)")
