#include "plumb/core/estimate.hpp"

#include <cmath>

namespace plumb {

bool Estimate::all_finite() const {
  for (double v : {t_start, t_end, inclination_deg, azimuth_deg, gravity_toolface_deg, magnetic_toolface_deg, rpm,
                   inclination_sd_deg, azimuth_sd_deg, toolface_sd_deg, dip_deg, total_g, total_b}) {
    if (!std::isfinite(v)) return false;
  }
  if (navigation) {
    for (const auto* a : {&navigation->position_m, &navigation->velocity_mps, &navigation->position_sd_m,
                          &navigation->velocity_sd_mps})
      for (double v : *a)
        if (!std::isfinite(v)) return false;
  }
  return true;
}

}  // namespace plumb
