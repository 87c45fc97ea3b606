// One station from every valid window of a stop. Windows that do not overlap are independent
// measurements of the same attitude: their inverse-variance weighted mean has the information of
// the whole still period (for a windowed estimator at its Cramer-Rao bound, the bound of the stop's
// length), and its sigma is 1 / sqrt(sum of weights), widened by the scatter of the windows about
// the mean when that scatter is larger than their sigmas say (Birge ratio). A navigator's rows are
// not independent (each carries the filter's whole past): its last row of the stop is the station.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "plumb/core/estimate.hpp"

namespace plumb::survey {

struct CombinedAttitude {
  double t_end = 0;                    // of the last window used
  double inclination_deg = 0, inclination_sd_deg = 0;
  double azimuth_deg = std::numeric_limits<double>::quiet_NaN(), azimuth_sd_deg = 0;
  bool azimuth_valid = false;
  double toolface_deg = std::numeric_limits<double>::quiet_NaN();  // gravity toolface
  double toolface_sd_deg = std::numeric_limits<double>::quiet_NaN();
  double total_g = 0, total_b = 0, dip_deg = 0;  // 0: not measured
  std::size_t windows = 0;             // windows combined
};

// `windows` in time order, all valid, at least one.
CombinedAttitude combine_stop(const std::vector<Estimate>& windows);

}  // namespace plumb::survey
