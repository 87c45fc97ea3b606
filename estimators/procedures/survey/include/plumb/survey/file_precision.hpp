// The precision a survey file holds each kind of number to (docs/surveys.md, "The survey file"):
// depths and positions to 0.001 m, angles to 0.001 deg, |G| to 1e-5 m/s^2, |B| to 0.001 uT, times
// to 0.001 s, standard deviations to 3 significant digits (below 1e-6 of their unit: 0). A station
// enters a survey already rounded this way (Survey::add), so the file's text reads back as the very
// same numbers and a restarted plumb-survey recomputes the same survey, digit for digit.
#pragma once

#include <cmath>

namespace plumb::survey::precision {

inline constexpr int kMetreDecimals = 3;
inline constexpr int kDegreeDecimals = 3;
inline constexpr int kSecondDecimals = 3;
inline constexpr int kGravityDecimals = 5;
inline constexpr int kFieldDecimals = 3;
inline constexpr int kSigmaDigits = 3;
inline constexpr double kSigmaFloor = 1e-6;

// The double nearest to v rounded to `decimals` places: k / 10^decimals, which is also what the
// text of k with that many decimals reads back as. Non-finite values are kept.
inline double round_decimals(double v, int decimals) {
  if (!std::isfinite(v)) return v;
  const double scale = std::pow(10.0, decimals);
  return std::round(v * scale) / scale;
}

// A standard deviation to kSigmaDigits significant digits; below kSigmaFloor (the arithmetic's
// noise, not a measurement) 0. Non-finite values are kept.
inline double round_sigma(double v) {
  if (!std::isfinite(v) || std::abs(v) < kSigmaFloor) return std::isfinite(v) ? 0.0 : v;
  const int e = static_cast<int>(std::floor(std::log10(std::abs(v)))) - (kSigmaDigits - 1);
  if (e >= 0) {
    const double p = std::pow(10.0, e);
    return std::round(v / p) * p;
  }
  const double q = std::pow(10.0, -e);
  return std::round(v * q) / q;
}

}  // namespace plumb::survey::precision
