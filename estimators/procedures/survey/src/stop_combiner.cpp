#include "plumb/survey/stop_combiner.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>

#include "plumb/core/attitude.hpp"

namespace plumb::survey {
namespace {

struct Mean {
  double value = std::numeric_limits<double>::quiet_NaN();
  double sd = 0;
};

// Weighted mean of angles near each other (offsets from the first, so that 359 and 1 average to 0)
// with the sigma of the mean. A window without a sigma (0: not estimated) makes every weight equal,
// and the sigma then comes from the scatter alone.
Mean mean_of(const std::vector<const Estimate*>& w, const std::function<double(const Estimate&)>& value,
             const std::function<double(const Estimate&)>& sd, bool circular) {
  Mean m;
  if (w.empty()) return m;
  bool all_sd = true;
  for (const Estimate* e : w) all_sd = all_sd && std::isfinite(sd(*e)) && sd(*e) > 0;
  const double ref = value(*w.front());
  const auto offset = [&](const Estimate& e) { return circular ? wrap_deg_180(value(e) - ref) : value(e) - ref; };
  double sw = 0, swx = 0;
  for (const Estimate* e : w) {
    const double weight = all_sd ? 1.0 / (sd(*e) * sd(*e)) : 1.0;
    sw += weight;
    swx += weight * offset(*e);
  }
  const double mean_offset = swx / sw;
  double chi2 = 0;
  for (const Estimate* e : w) {
    const double r = offset(*e) - mean_offset;
    chi2 += all_sd ? r * r / (sd(*e) * sd(*e)) : r * r;
  }
  const double n = static_cast<double>(w.size());
  if (all_sd) {
    m.sd = 1.0 / std::sqrt(sw);
    if (n > 1 && chi2 > n - 1) m.sd *= std::sqrt(chi2 / (n - 1));
  } else {
    m.sd = n > 1 ? std::sqrt(chi2 / (n - 1) / n) : 0.0;
  }
  m.value = ref + mean_offset;
  if (circular) m.value = std::fmod(m.value + 720.0, 360.0);
  return m;
}

}  // namespace

CombinedAttitude combine_stop(const std::vector<Estimate>& windows) {
  if (windows.empty()) throw std::invalid_argument("combine_stop: no window");
  std::vector<const Estimate*> used;
  if (windows.back().navigation) {
    used.push_back(&windows.back());
  } else {
    // Windows that overlap share samples: the later of two is left out.
    for (const Estimate& e : windows)
      if (used.empty() || e.t_start >= used.back()->t_end - 1e-9) used.push_back(&e);
  }
  CombinedAttitude c;
  c.windows = used.size();
  c.t_end = used.back()->t_end;
  const Mean inc = mean_of(used, [](const Estimate& e) { return e.inclination_deg; },
                           [](const Estimate& e) { return e.inclination_sd_deg; }, false);
  c.inclination_deg = inc.value;
  c.inclination_sd_deg = inc.sd;
  std::vector<const Estimate*> with_azimuth, with_toolface;
  bool rotating = false;
  for (const Estimate* e : used) {
    if (e->azimuth_valid && std::isfinite(e->azimuth_deg)) with_azimuth.push_back(e);
    if (e->toolface_valid && std::isfinite(e->gravity_toolface_deg)) with_toolface.push_back(e);
    rotating = rotating || e->rotating;
  }
  c.azimuth_valid = !with_azimuth.empty();
  if (c.azimuth_valid) {
    const Mean az = mean_of(with_azimuth, [](const Estimate& e) { return e.azimuth_deg; },
                            [](const Estimate& e) { return e.azimuth_sd_deg; }, true);
    c.azimuth_deg = az.value;
    c.azimuth_sd_deg = az.sd;
  } else if (std::isfinite(used.back()->azimuth_deg)) {
    c.azimuth_deg = used.back()->azimuth_deg;
    c.azimuth_sd_deg = used.back()->azimuth_sd_deg;
  }
  // A turning tool has no one toolface: the last window's, at its end. A standing one's is the mean.
  if (!with_toolface.empty()) {
    if (rotating) with_toolface.erase(with_toolface.begin(), with_toolface.end() - 1);
    const Mean tf = mean_of(with_toolface, [](const Estimate& e) { return e.gravity_toolface_deg; },
                            [](const Estimate& e) { return e.toolface_sd_deg; }, true);
    c.toolface_deg = tf.value;
    c.toolface_sd_deg = with_toolface.size() == 1 && !(with_toolface.front()->toolface_sd_deg > 0) ? 
        std::numeric_limits<double>::quiet_NaN() : tf.sd;
  }
  double g = 0, b = 0, dip = 0;
  std::size_t ng = 0, nb = 0;
  for (const Estimate* e : used) {
    if (e->total_g > 0) g += e->total_g, ++ng;
    if (e->total_b > 0) b += e->total_b, dip += e->dip_deg, ++nb;
  }
  if (ng) c.total_g = g / static_cast<double>(ng);
  if (nb) c.total_b = b / static_cast<double>(nb), c.dip_deg = dip / static_cast<double>(nb);
  return c;
}

}  // namespace plumb::survey
