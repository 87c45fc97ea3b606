// Station averaging that waits for the readings to settle (METHODS.md 2: "read repeatedly until
// the last readings repeat, at least three times").
#include <algorithm>
#include <cmath>
#include <sstream>

#include "plumb/calibration/types.hpp"

namespace plumb::calibration {

namespace {

constexpr int kChannels = 7;  // f xyz, b xyz, temperature

using Channels = Eigen::Matrix<double, kChannels, 1>;

Channels channels_of(const Sample& s) {
  Channels c;
  c << s.f, s.b, s.temp_c;
  return c;
}

struct Block {
  std::size_t first = 0, last = 0;  // sample indices [first, last)
  Channels mean = Channels::Zero();
  Channels sd = Channels::Zero();
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

std::string fmt(double x) {
  std::ostringstream o;
  o.precision(4);
  o << x;
  return o.str();
}

}  // namespace

StationAverage average_station(const std::vector<Sample>& samples, const Station& station,
                               const SettleOptions& options) {
  const std::string who = "station '" + station.name + "'";
  if (!(station.end_s > station.start_s)) throw CalibrationError(who + ": end time is not after start time");
  StationAverage out;
  out.station = station;
  std::vector<const Sample*> usable;
  for (const auto& s : samples) {
    if (s.t < station.start_s || s.t > station.end_s) continue;
    if ((s.flags & flags::kUnusable) || !s.f.allFinite() || !s.b.allFinite()) {
      ++out.samples_rejected;
      continue;
    }
    usable.push_back(&s);
  }
  out.has_temperature = !usable.empty() && std::all_of(usable.begin(), usable.end(), [](const Sample* s) {
    return (s->flags & flags::kHasTemperature) != 0;
  });

  // Readings: block means.
  std::vector<Block> blocks;
  std::size_t i = 0;
  while (i < usable.size()) {
    Block b;
    b.first = i;
    const double t0 = usable[i]->t;
    while (i < usable.size() && usable[i]->t < t0 + options.block_s) ++i;
    b.last = i;
    const double n = static_cast<double>(b.last - b.first);
    for (std::size_t k = b.first; k < b.last; ++k) b.mean += channels_of(*usable[k]);
    b.mean /= n;
    for (std::size_t k = b.first; k < b.last; ++k) b.sd += (channels_of(*usable[k]) - b.mean).cwiseAbs2();
    b.sd = (b.sd / std::max(1.0, n - 1)).cwiseSqrt();
    blocks.push_back(b);
  }
  // The last block is usually short: drop it from the settling test unless it is all there is.
  if (blocks.size() > 1 && blocks.back().last - blocks.back().first < (blocks.front().last - blocks.front().first) / 2)
    blocks.pop_back();
  const auto repeats = static_cast<std::size_t>(std::max(2, options.repeats));
  if (blocks.size() < repeats)
    throw CalibrationError(who + ": only " + std::to_string(usable.size()) + " usable samples in [" +
                           fmt(station.start_s) + ", " + fmt(station.end_s) + "] s, too few to see it settle (" +
                           std::to_string(repeats) + " readings of " + fmt(options.block_s) + " s needed)");

  // Tolerance per channel from the noise of one reading (robust to the transient inflating early
  // blocks' scatter), with absolute floors.
  const int checked = options.check_mag ? 6 : 3;
  Channels tol = Channels::Zero();
  for (int c = 0; c < checked; ++c) {
    std::vector<double> se, d2;
    for (const auto& b : blocks) se.push_back(b.sd[c] / std::sqrt(static_cast<double>(b.last - b.first)));
    // Counted outputs (pulses per unit time) can have no scatter within a reading yet jump by one
    // count between readings: the noise of a reading also comes from the second differences of
    // the readings, which a slow drift does not inflate.
    for (std::size_t k = 2; k < blocks.size(); ++k)
      d2.push_back(std::abs(blocks[k].mean[c] - 2 * blocks[k - 1].mean[c] + blocks[k - 2].mean[c]));
    const double from_d2 = d2.empty() ? 0.0 : median(d2) / (0.6745 * std::sqrt(6.0));
    const double floor = c < 3 ? options.min_tolerance_accel : options.min_tolerance_mag;
    tol[c] = std::max(options.k_sigma * std::max(median(se), from_d2), floor);
    if (tol[c] <= 0) tol[c] = 1e-12;  // a noise-free channel must repeat exactly
  }

  std::size_t settled = blocks.size();
  for (std::size_t k = repeats - 1; k < blocks.size(); ++k) {
    bool agree = true;
    for (int c = 0; c < checked && agree; ++c) {
      double lo = blocks[k].mean[c], hi = lo;
      for (std::size_t j = k + 1 - repeats; j <= k; ++j) {
        lo = std::min(lo, blocks[j].mean[c]);
        hi = std::max(hi, blocks[j].mean[c]);
      }
      agree = hi - lo <= tol[c];
    }
    if (agree) {
      settled = k + 1 - repeats;
      break;
    }
  }
  if (settled == blocks.size()) {
    Channels lo = blocks.back().mean, hi = lo;
    for (std::size_t j = blocks.size() - repeats; j < blocks.size(); ++j) {
      lo = lo.cwiseMin(blocks[j].mean);
      hi = hi.cwiseMax(blocks[j].mean);
    }
    const Channels change = hi - lo;
    int worst = 0;
    for (int c = 1; c < checked; ++c)
      if (change[c] / tol[c] > change[worst] / tol[worst]) worst = c;
    static const char* const kNames[] = {"fx", "fy", "fz", "bx", "by", "bz", "temp"};
    throw CalibrationError(who + ": never settled: the last " + std::to_string(repeats) + " readings of " +
                           kNames[worst] + " still differ by " + fmt(change[worst]) + " (tolerance " +
                           fmt(tol[worst]) + ")");
  }

  // Average from the end of the repeating readings to the end of the station: the tail of the
  // settling transient left in the repeating readings would otherwise bias a short station's mean
  // by a fair fraction of its standard error.
  const std::size_t after = settled + repeats;
  const std::size_t first = after < blocks.size() ? blocks[after].first : blocks[settled + repeats - 1].first;
  Channels mean = Channels::Zero(), var = Channels::Zero();
  const auto n = static_cast<double>(usable.size() - first);
  for (std::size_t k = first; k < usable.size(); ++k) mean += channels_of(*usable[k]);
  mean /= n;
  for (std::size_t k = first; k < usable.size(); ++k) var += (channels_of(*usable[k]) - mean).cwiseAbs2();
  var /= std::max(1.0, n - 1);
  const Channels se = (var / n).cwiseSqrt();
  out.accel = mean.segment<3>(0);
  out.accel_se = se.segment<3>(0);
  out.mag = mean.segment<3>(3);
  out.mag_se = se.segment<3>(3);
  out.raw_temp_c = mean[6];
  out.raw_temp_se = se[6];
  out.samples_used = usable.size() - first;
  out.settled_after_s = usable[first]->t - station.start_s;
  return out;
}

std::vector<StationAverage> average_stations(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                                             const SettleOptions& options) {
  std::vector<StationAverage> out;
  out.reserve(stations.size());
  for (const auto& st : stations) out.push_back(average_station(samples, st, options));
  return out;
}

}  // namespace plumb::calibration
