#include "plumb/compare/agreement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace plumb::compare {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double wrap_180(double deg) { return deg - 360.0 * std::floor((deg + 180.0) / 360.0); }

// Of the sigmas reported: an unknown one (NaN) is left out, and none known is NaN.
double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::erase_if(v, [](double x) { return std::isnan(x); });
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

PluginSummary summarize(const std::string& name, const std::vector<Estimate>& rows) {
  PluginSummary s;
  s.name = name;
  s.rows = rows.size();
  double c = 0, sn = 0;
  std::vector<double> inclinations, inc_sigma, azi_sigma;
  for (const Estimate& e : rows) {
    if (!e.valid) continue;
    ++s.valid;
    inclinations.push_back(e.inclination_deg);
    inc_sigma.push_back(e.inclination_sd_deg);
    if (!e.azimuth_valid) continue;
    ++s.azimuth_valid;
    c += std::cos(e.azimuth_deg * kDeg);
    sn += std::sin(e.azimuth_deg * kDeg);
    azi_sigma.push_back(e.azimuth_sd_deg);
  }
  if (s.valid > 0) {
    // Two passes: a steady tool's inclinations agree to 1e-7 deg, below the rounding of sum x^2.
    const double n = static_cast<double>(s.valid);
    double sum = 0, square_sum = 0;
    for (const double x : inclinations) sum += x;
    s.inclination_mean_deg = sum / n;
    for (const double x : inclinations) square_sum += (x - s.inclination_mean_deg) * (x - s.inclination_mean_deg);
    s.inclination_sd_deg = std::sqrt(square_sum / n);
    s.median_inclination_sigma_deg = median(inc_sigma);
  }
  if (s.azimuth_valid > 0) {
    // Circular mean and standard deviation (sqrt(-2 ln R)): 359 and 1 deg average to 0, not 180.
    const double n = static_cast<double>(s.azimuth_valid);
    const double r = std::min(1.0, std::hypot(c, sn) / n);
    s.azimuth_mean_deg = std::fmod(std::atan2(sn, c) / kDeg + 360.0, 360.0);
    s.azimuth_sd_deg = r > 0 ? std::sqrt(std::max(0.0, -2.0 * std::log(r))) / kDeg : 180.0;
    s.median_azimuth_sigma_deg = median(azi_sigma);
  }
  return s;
}

Agreement agree(const std::vector<Estimate>& reference, const std::vector<Estimate>& other, double match_s) {
  std::vector<const Estimate*> ref;
  for (const Estimate& e : reference)
    if (e.valid) ref.push_back(&e);
  Agreement a;
  double inc2 = 0, azi2 = 0;
  std::size_t azi_n = 0, inc_sigma_n = 0, inc_within = 0, azi_sigma_n = 0, azi_within = 0;
  std::size_t j = 0;
  for (const Estimate& e : other) {
    if (!e.valid || ref.empty()) continue;
    while (j + 1 < ref.size() && std::abs(ref[j + 1]->t_end - e.t_end) <= std::abs(ref[j]->t_end - e.t_end)) ++j;
    const Estimate& r = *ref[j];
    if (std::abs(r.t_end - e.t_end) > match_s) continue;
    ++a.matched;
    const double di = e.inclination_deg - r.inclination_deg;
    inc2 += di * di;
    if (e.inclination_sd_deg > 0 && r.inclination_sd_deg > 0) {
      ++inc_sigma_n;
      if (std::abs(di) <= 2.0 * std::hypot(e.inclination_sd_deg, r.inclination_sd_deg)) ++inc_within;
    }
    if (e.azimuth_valid && r.azimuth_valid) {
      const double da = wrap_180(e.azimuth_deg - r.azimuth_deg);
      azi2 += da * da;
      ++azi_n;
      if (e.azimuth_sd_deg > 0 && r.azimuth_sd_deg > 0) {
        ++azi_sigma_n;
        if (std::abs(da) <= 2.0 * std::hypot(e.azimuth_sd_deg, r.azimuth_sd_deg)) ++azi_within;
      }
    }
  }
  if (a.matched > 0) a.rms_inclination_diff_deg = std::sqrt(inc2 / static_cast<double>(a.matched));
  if (azi_n > 0) a.rms_azimuth_diff_deg = std::sqrt(azi2 / static_cast<double>(azi_n));
  if (inc_sigma_n > 0) a.inclination_within_2sigma = static_cast<double>(inc_within) / static_cast<double>(inc_sigma_n);
  if (azi_sigma_n > 0) a.azimuth_within_2sigma = static_cast<double>(azi_within) / static_cast<double>(azi_sigma_n);
  return a;
}

}  // namespace plumb::compare
