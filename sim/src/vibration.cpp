#include "plumb/sim/vibration.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace plumb::sim {

VibrationTones::VibrationTones(const Vibration& v, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const bool broadband = v.band_hz > 0;
  const int tones = broadband ? kBroadbandTones : kNarrowTones;
  for (int axis = 0; axis < 2; ++axis) {
    for (int k = 0; k < tones; ++k) {
      // (The narrow tones draw the phase only, in this order: a seed's runs stay as they were.)
      const double f = broadband ? v.frequency_hz + v.band_hz * (unit(rng) - 0.5)
                                 : v.frequency_hz * (0.75 + 0.5 * k / (kNarrowTones - 1));
      frequency_[axis].push_back(f);
      phase_[axis].push_back(2.0 * std::numbers::pi * unit(rng));
    }
  }
  amplitude_ = v.lateral_rms * std::sqrt(2.0 / tones);
}

Eigen::Vector2d VibrationTones::at(double t) const {
  Eigen::Vector2d out = Eigen::Vector2d::Zero();
  if (!active()) return out;
  for (int axis = 0; axis < 2; ++axis)
    for (std::size_t k = 0; k < frequency_[axis].size(); ++k)
      out[axis] += amplitude_ * std::sin(2.0 * std::numbers::pi * frequency_[axis][k] * t + phase_[axis][k]);
  return out;
}

std::string vibration_problem(const Vibration& v) {
  if (!(std::isfinite(v.lateral_rms) && v.lateral_rms >= 0)) return "vibration rms must be >= 0";
  if (!(std::isfinite(v.frequency_hz) && v.frequency_hz > 0)) return "vibration frequency must be > 0 Hz";
  if (!(std::isfinite(v.band_hz) && v.band_hz >= 0 && v.band_hz < 2.0 * v.frequency_hz))
    return "vibration band must be >= 0 Hz and below twice the centre frequency (its lowest tone above 0 Hz)";
  return {};
}

std::string describe(const Vibration& v) {
  std::ostringstream out;
  out << v.lateral_rms << " m/s2 rms ";
  if (v.band_hz > 0) {
    out << "over " << v.frequency_hz - v.band_hz / 2 << "-" << v.frequency_hz + v.band_hz / 2 << " Hz";
  } else {
    out << "at " << v.frequency_hz << " Hz";
  }
  return out.str();
}

}  // namespace plumb::sim
