// Plugins side by side on a recording, where there is no truth (`plumb compare` on
// recordings): what each plugin says (its spread over the run and the sigma it reports), and how
// far each stands from a reference plugin against their combined sigma. Two honest estimators of
// one tool differ by less than 2 sqrt(s1^2 + s2^2) about 95 % of the time; far fewer means that
// one of them errs or understates its sigma.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "plumb/core/estimate.hpp"

namespace plumb::compare {

struct PluginSummary {
  std::string name;
  std::size_t rows = 0, valid = 0, azimuth_valid = 0;
  double inclination_mean_deg = 0, inclination_sd_deg = 0;  // over the valid rows
  double azimuth_mean_deg = 0, azimuth_sd_deg = 0;          // circular, over the azimuth-valid rows
  double median_inclination_sigma_deg = 0;                  // what the plugin reports (0: none)
  double median_azimuth_sigma_deg = 0;
};

struct Agreement {
  std::size_t matched = 0;           // rows of the other plugin with a reference row close in time
  double rms_inclination_diff_deg = 0;
  double rms_azimuth_diff_deg = 0;   // differences wrapped to [-180, 180)
  // Fraction of matched rows whose difference is within 2 sqrt(s1^2 + s2^2); negative when the
  // plugins report no sigma for that angle.
  double inclination_within_2sigma = -1;
  double azimuth_within_2sigma = -1;
};

PluginSummary summarize(const std::string& name, const std::vector<Estimate>& rows);
// Rows are matched by their end time: each valid row of `other` with the valid `reference` row
// nearest in time, when they are at most `match_s` apart. Both lists in time order.
Agreement agree(const std::vector<Estimate>& reference, const std::vector<Estimate>& other, double match_s);

}  // namespace plumb::compare
