// Station averaging that waits for the readings to settle (docs/methods.md section 2: "read repeatedly until
// the last readings repeat, at least three times").
#include <algorithm>
#include <cmath>
#include <sstream>

#include "plumb/calibration/types.hpp"

namespace plumb::calibration {

namespace {

constexpr int kChannels = 10;  // f xyz, b xyz, temperature, w xyz
constexpr int kTemp = 6;
const char* const kNames[kChannels] = {"fx", "fy", "fz", "bx", "by", "bz", "temp", "wx", "wy", "wz"};

using Channels = Eigen::Matrix<double, kChannels, 1>;

Channels channels_of(const Sample& s) {
  Channels c;
  c << s.f, s.b, s.temp_c, s.w;
  return c;
}

// A still part of a station: blocks [settle, end), averaged from `first` (after the repeating
// readings that showed it had settled).
struct Segment {
  std::size_t settle = 0, first = 0, end = 0;
  Channels mean = Channels::Zero();
};

struct Block {
  std::size_t first = 0, last = 0;  // sample indices [first, last)
  Channels mean = Channels::Zero();
  Channels sd = Channels::Zero();
};

double upper_median(std::vector<double> v) {
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

// Settling tolerance of one channel: k_sigma times the noise of one reading (robust to the
// transient inflating early blocks' scatter), at least `floor`.
double channel_tolerance(const std::vector<Block>& blocks, int c, double k_sigma, double floor) {
  std::vector<double> se, d2;
  for (const auto& b : blocks) se.push_back(b.sd[c] / std::sqrt(static_cast<double>(b.last - b.first)));
  // Counted outputs (pulses per unit time) can have no scatter within a reading yet jump by one
  // count between readings: the noise of a reading also comes from the second differences of
  // the readings, which a slow drift does not inflate.
  for (std::size_t k = 2; k < blocks.size(); ++k)
    d2.push_back(std::abs(blocks[k].mean[c] - 2 * blocks[k - 1].mean[c] + blocks[k - 2].mean[c]));
  const double from_d2 = d2.empty() ? 0.0 : upper_median(d2) / (0.6745 * std::sqrt(6.0));
  const double tol = std::max(k_sigma * std::max(upper_median(se), from_d2), floor);
  return tol > 0 ? tol : 1e-12;  // a noise-free channel must repeat exactly
}

// The samples of the station's window that can be used; the rest are counted as rejected.
std::vector<const Sample*> usable_samples(const std::vector<Sample>& samples, const Station& station,
                                          StationAverage& out) {
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
  return usable;
}

// Readings: block means of block_s each. The last block is usually short: dropped from the
// settling test unless it is all there is.
std::vector<Block> readings(const std::vector<const Sample*>& usable, double block_s) {
  std::vector<Block> blocks;
  std::size_t i = 0;
  while (i < usable.size()) {
    Block b;
    b.first = i;
    const double t0 = usable[i]->t;
    while (i < usable.size() && usable[i]->t < t0 + block_s) ++i;
    b.last = i;
    const double n = static_cast<double>(b.last - b.first);
    for (std::size_t k = b.first; k < b.last; ++k) b.mean += channels_of(*usable[k]);
    b.mean /= n;
    for (std::size_t k = b.first; k < b.last; ++k) b.sd += (channels_of(*usable[k]) - b.mean).cwiseAbs2();
    b.sd = (b.sd / std::max(1.0, n - 1)).cwiseSqrt();
    blocks.push_back(b);
  }
  if (blocks.size() > 1 && blocks.back().last - blocks.back().first < (blocks.front().last - blocks.front().first) / 2)
    blocks.pop_back();
  return blocks;
}

// What counts as motion on each channel the stillness is judged on.
struct Motion {
  std::vector<int> channels;
  Channels quantum = Channels::Zero();       // a counted output's step
  Channels tol = Channels::Constant(1e-12);  // settling tolerance of a reading
  Channels sample_sd = Channels::Zero();     // typical scatter of one sample
};

Motion motion_tolerances(const std::vector<const Sample*>& usable, const std::vector<Block>& blocks,
                         const SettleOptions& options) {
  Motion m;
  // The tool is still when every sensor says so: accelerometers and magnetometers always (a
  // magnetometer still turning after a turntable move is a move), gyros when the package has them.
  // Settling and motion are judged on the same channels.
  const bool has_gyro = !usable.empty() && std::all_of(usable.begin(), usable.end(), [](const Sample* s) {
    return (s->flags & flags::kHasGyro) != 0;
  });
  m.channels = {0, 1, 2, 3, 4, 5};
  if (has_gyro) m.channels.insert(m.channels.end(), {7, 8, 9});
  // Counted outputs step by one count: a channel that sits on one count for most of a station has
  // almost no noise, yet one count more in one sample is no motion. The count (the smallest step
  // between samples) sets a floor: two counts in a reading, half a count for a sample's scatter.
  for (int c : m.channels) {
    double q = 0;
    for (std::size_t k = 1; k < usable.size(); ++k) {
      const double d = std::abs(channels_of(*usable[k])[c] - channels_of(*usable[k - 1])[c]);
      if (d > 1e-9 * std::abs(channels_of(*usable[k])[c]) && (q == 0 || d < q)) q = d;
    }
    m.quantum[c] = q;
  }
  const double n_block = static_cast<double>(blocks.front().last - blocks.front().first);
  for (int c : m.channels)
    m.tol[c] = channel_tolerance(blocks, c, options.k_sigma,
                                 std::max(2 * m.quantum[c] / n_block,
                                          c < 3 ? options.min_tolerance_accel : c < 6 ? options.min_tolerance_mag : 0));

  // Motion shows as a step between readings or as excess scatter within one. The steps are judged
  // against twice the settling tolerance (8 sigma of a reading: no false alarm over hundreds of
  // stations), the scatter against 4 times the typical scatter of a sample.
  for (int c : m.channels) {
    std::vector<double> sds;
    for (const auto& b : blocks) sds.push_back(b.sd[c]);
    // Counted outputs can show no scatter inside most readings: the reading-to-reading noise,
    // scaled to one sample, is the floor.
    m.sample_sd[c] = std::max({upper_median(sds), m.tol[c] / options.k_sigma * std::sqrt(n_block), 0.5 * m.quantum[c]});
  }
  return m;
}

// Still segments: settle (the repeating readings), then stay until a reading is disturbed; the
// disturbances (time, channel) between them are appended.
std::vector<Segment> still_segments(const std::vector<const Sample*>& usable, const std::vector<Block>& blocks,
                                    const Motion& m, std::size_t repeats,
                                    std::vector<std::pair<double, int>>& disturbances) {
  const auto disturbed = [&](std::size_t k, const Channels& reference, int& channel) {
    for (int c : m.channels) {
      if (std::abs(blocks[k].mean[c] - reference[c]) > 2 * m.tol[c] || blocks[k].sd[c] > 4 * m.sample_sd[c]) {
        channel = c;
        return true;
      }
    }
    return false;
  };
  const auto settles_at = [&](std::size_t k) {
    for (int c : m.channels) {
      double lo = blocks[k].mean[c], hi = lo;
      for (std::size_t j = k + 1 - repeats; j <= k; ++j) {
        lo = std::min(lo, blocks[j].mean[c]);
        hi = std::max(hi, blocks[j].mean[c]);
      }
      if (hi - lo > m.tol[c]) return false;
    }
    return true;
  };

  std::vector<Segment> segments;
  std::size_t from = 0;
  while (from + repeats <= blocks.size()) {
    std::size_t k = from + repeats - 1;
    while (k < blocks.size() && !settles_at(k)) ++k;
    if (k >= blocks.size()) break;
    Segment seg;
    seg.settle = k + 1 - repeats;
    std::size_t j = k + 1;
    int channel = 0;
    for (; j < blocks.size(); ++j) {
      Channels reference = Channels::Zero();
      for (std::size_t q = j - repeats; q < j; ++q) reference += blocks[q].mean;
      if (disturbed(j, reference / static_cast<double>(repeats), channel)) break;
    }
    seg.end = j;
    seg.first = seg.settle + repeats < seg.end ? seg.settle + repeats : seg.end - 1;
    for (std::size_t q = seg.first; q < seg.end; ++q) seg.mean += blocks[q].mean;
    seg.mean /= static_cast<double>(seg.end - seg.first);
    segments.push_back(seg);
    if (j < blocks.size()) disturbances.emplace_back(usable[blocks[j].first]->t, channel);
    from = j + 1;
  }
  return segments;
}

// Never settled: names the channel that changed most, relative to its tolerance, over the last readings.
[[noreturn]] void never_settled(const std::string& who, const std::vector<Block>& blocks, const Motion& m,
                                std::size_t repeats, const std::vector<std::pair<double, int>>& disturbances) {
  Channels lo = blocks.back().mean, hi = lo;
  for (std::size_t j = blocks.size() - repeats; j < blocks.size(); ++j) {
    lo = lo.cwiseMin(blocks[j].mean);
    hi = hi.cwiseMax(blocks[j].mean);
  }
  const Channels change = hi - lo;
  int worst = 0;
  for (int c : m.channels)
    if (change[c] / m.tol[c] > change[worst] / m.tol[worst]) worst = c;
  std::string moved;
  if (!disturbances.empty()) moved = " (moving since t = " + fmt(disturbances.front().first) + " s)";
  throw CalibrationError(who + ": never settled: the last " + std::to_string(repeats) + " readings of " +
                         kNames[worst] + " still differ by " + fmt(change[worst]) + " (tolerance " +
                         fmt(m.tol[worst]) + ")" + moved);
}

// The longest still part is the station. Another still part at a different place is refused
// unless the tool came back (a still part at the station's place before and after it): then it was
// an excursion (lifted and put back). Otherwise which place was meant cannot be told.
const Segment& the_station(const std::string& who, const Station& station, const std::vector<const Sample*>& usable,
                           const std::vector<Block>& blocks, const Motion& m, const std::vector<Segment>& segments) {
  const auto at = [&](std::size_t block) { return fmt(usable[blocks[block].first]->t); };
  std::size_t longest = 0;
  for (std::size_t k = 1; k < segments.size(); ++k)
    if (segments[k].end - segments[k].first > segments[longest].end - segments[longest].first) longest = k;
  const Segment& use = segments[longest];
  const auto same_place = [&](const Segment& a, int& channel) {
    for (int c : m.channels)
      if (std::abs(a.mean[c] - use.mean[c]) > 2 * m.tol[c]) {
        channel = c;
        return false;
      }
    return true;
  };
  std::vector<bool> home(segments.size());
  for (std::size_t k = 0; k < segments.size(); ++k) {
    int channel = 0;
    home[k] = same_place(segments[k], channel);
  }
  for (std::size_t k = 0; k < segments.size(); ++k) {
    int channel = 0;
    if (same_place(segments[k], channel)) continue;
    const bool back_before = std::any_of(home.begin(), home.begin() + static_cast<long>(k), [](bool h) { return h; });
    const bool back_after = std::any_of(home.begin() + static_cast<long>(k) + 1, home.end(), [](bool h) { return h; });
    if (back_before && back_after) continue;
    // The disturbance between the two places: the one that ended the earlier of them.
    const Segment& earlier = k < longest ? segments[k] : use;
    const double when = usable[blocks[std::min(earlier.end, blocks.size() - 1)].first]->t;
    throw CalibrationError(who + ": the tool moved at t = " + fmt(when) + " s and was still at another place (" +
                           kNames[channel] + " differs by " + fmt(std::abs(segments[k].mean[channel] - use.mean[channel])) +
                           ", tolerance " + fmt(2 * m.tol[channel]) + ") from t = " + at(segments[k].settle) +
                           " to " + (segments[k].end < blocks.size() ? at(segments[k].end) : fmt(station.end_s)) +
                           " s: the window holds more than one position; cut it to one or repeat the station");
  }
  return use;
}

// The station's averages and their standard errors, from the end of the repeating readings to
// the end of the still part `use`.
void station_means(const Station& station, const std::vector<const Sample*>& usable, const std::vector<Block>& blocks,
                   const Segment& use, const Motion& m, StationAverage& out) {
  // Average from the end of the repeating readings to the end of the still part: the tail of the
  // settling transient left in the repeating readings would otherwise bias a short station's mean
  // by a fair fraction of its standard error.
  const std::size_t first = blocks[use.first].first;
  const std::size_t last = use.end < blocks.size() ? blocks[use.end].first : usable.size();
  Channels mean = Channels::Zero(), var = Channels::Zero();
  const auto n = static_cast<double>(last - first);
  for (std::size_t k = first; k < last; ++k) mean += channels_of(*usable[k]);
  mean /= n;
  for (std::size_t k = first; k < last; ++k) var += (channels_of(*usable[k]) - mean).cwiseAbs2();
  var /= std::max(1.0, n - 1);
  Channels se = (var / n).cwiseSqrt();
  // Counted outputs: the scatter of single samples is mostly quantisation that the counting
  // carries over from sample to sample, so it overstates the error of the mean. The scatter of
  // the readings (1 s counts) is the better estimate then; it is used where it is less than half
  // the sample-based one (never for white noise, where the two agree).
  const std::size_t nb = std::min(use.end, blocks.size()) - use.first;
  if (nb >= 5) {
    Channels bm = Channels::Zero(), bv = Channels::Zero();
    for (std::size_t q = use.first; q < use.first + nb; ++q) bm += blocks[q].mean;
    bm /= static_cast<double>(nb);
    for (std::size_t q = use.first; q < use.first + nb; ++q) bv += (blocks[q].mean - bm).cwiseAbs2();
    const Channels se_blocks = (bv / static_cast<double>(nb - 1) / static_cast<double>(nb)).cwiseSqrt();
    for (int c = 0; c < kChannels; ++c)
      if (se_blocks[c] < 0.5 * se[c]) se[c] = se_blocks[c];
  }
  // A counted channel can sit on one count for a whole station (noise well below a count per
  // sample): its scatter is then nil, yet its mean is known only to about a count over the average
  // (the counting's phase at both ends: sd = count / (sqrt(6) n)). That is the floor.
  for (int c : m.channels) se[c] = std::max(se[c], m.quantum[c] / (std::sqrt(6.0) * n));
  out.accel = mean.segment<3>(0);
  out.accel_se = se.segment<3>(0);
  out.mag = mean.segment<3>(3);
  out.mag_se = se.segment<3>(3);
  out.raw_temp_c = mean[kTemp];
  out.raw_temp_se = se[kTemp];
  out.samples_used = last - first;
  out.settled_after_s = usable[first]->t - station.start_s;
}

}  // namespace

StationAverage average_station(const std::vector<Sample>& samples, const Station& station,
                               const SettleOptions& options) {
  const std::string who = "station '" + station.name + "'";
  if (!(station.end_s > station.start_s)) throw CalibrationError(who + ": end time is not after start time");
  StationAverage out;
  out.station = station;
  const std::vector<const Sample*> usable = usable_samples(samples, station, out);
  const std::vector<Block> blocks = readings(usable, options.block_s);
  const auto repeats = static_cast<std::size_t>(std::max(2, options.repeats));
  if (blocks.size() < repeats)
    throw CalibrationError(who + ": only " + std::to_string(usable.size()) + " usable samples in [" +
                           fmt(station.start_s) + ", " + fmt(station.end_s) + "] s, too few to see it settle (" +
                           std::to_string(repeats) + " readings of " + fmt(options.block_s) + " s needed)");
  const Motion m = motion_tolerances(usable, blocks, options);
  std::vector<std::pair<double, int>> disturbances;  // time, channel
  const std::vector<Segment> segments = still_segments(usable, blocks, m, repeats, disturbances);
  if (segments.empty()) never_settled(who, blocks, m, repeats, disturbances);
  const Segment& use = the_station(who, station, usable, blocks, m, segments);
  const auto at = [&](std::size_t block) { return fmt(usable[blocks[block].first]->t); };
  if (!disturbances.empty()) {
    std::string times;
    for (const auto& [t, c] : disturbances) times += (times.empty() ? "" : ", ") + fmt(t) + " s (" + kNames[c] + ")";
    out.notes.push_back(who + ": motion at t = " + times + "; used the still part from " + at(use.first) + " to " +
                        (use.end < blocks.size() ? at(use.end) : fmt(station.end_s)) + " s");
  }
  station_means(station, usable, blocks, use, m, out);
  return out;
}

std::vector<StationAverage> average_stations(const std::vector<Sample>& samples, const std::vector<Station>& stations,
                                             const SettleOptions& options) {
  // One window, one position: overlapping windows share samples (and a move) between stations.
  std::vector<const Station*> by_start;
  for (const auto& st : stations) by_start.push_back(&st);
  std::sort(by_start.begin(), by_start.end(), [](const Station* a, const Station* b) { return a->start_s < b->start_s; });
  for (std::size_t k = 1; k < by_start.size(); ++k)
    if (by_start[k]->start_s < by_start[k - 1]->end_s)
      throw CalibrationError("stations '" + by_start[k - 1]->name + "' [" + fmt(by_start[k - 1]->start_s) + ", " +
                             fmt(by_start[k - 1]->end_s) + "] s and '" + by_start[k]->name + "' [" +
                             fmt(by_start[k]->start_s) + ", " + fmt(by_start[k]->end_s) +
                             "] s overlap: each window must hold one position");
  std::vector<StationAverage> out;
  out.reserve(stations.size());
  for (const auto& st : stations) out.push_back(average_station(samples, st, options));
  return out;
}

}  // namespace plumb::calibration
