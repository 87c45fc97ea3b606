// atan2 to ~1e-14 rad at a fraction of libm's cost: the per-sample toolface is the hot spot of
// the rotating estimators (goal: 20 million samples per second per core).
#pragma once

#include <cmath>

namespace plumb::windowed {

namespace detail {
// tan(k pi/16) and k pi/16, k = 0..4: centres of the reduction atan(x) = atan(c) + atan((x-c)/(1+cx)).
inline constexpr double kTanCentre[5] = {0.0, 0.19891236737965800691, 0.41421356237309504880,
                                         0.66817863791929891999, 1.0};
inline constexpr double kAngleCentre[5] = {0.0, 0.19634954084936207740, 0.39269908169872415481,
                                           0.58904862254808623221, 0.78539816339744830962};
// tan((k + 1/2) pi/16): boundaries between centres.
inline constexpr double kBoundary[4] = {0.09849140335716425, 0.30334668360734239, 0.53451113595079149,
                                        0.82067879082866024};

// atan(lo / hi) for 0 <= lo <= hi, hi > 0, with a single division: x = lo/hi never formed, the
// reduced argument (x - c)/(1 + c x) is (lo - c hi)/(hi + c lo).
inline double atan_ratio(double lo, double hi) {
  // Branch-free choice of the centre: rotating data make these comparisons unpredictable.
  const int k = (lo > kBoundary[0] * hi) + (lo > kBoundary[1] * hi) + (lo > kBoundary[2] * hi) + (lo > kBoundary[3] * hi);
  const double c = kTanCentre[k];
  const double r = (lo - c * hi) / (hi + c * lo);  // |r| <= tan(pi/32) ~ 0.0985
  const double r2 = r * r;
  // Taylor series to r^11 (remainder < r^13/13 ~ 1e-14), evaluated by Estrin's scheme: three
  // independent pairs instead of one long Horner chain, so consecutive samples overlap in the CPU.
  constexpr double c3 = 1.0 / 3, c5 = 1.0 / 5, c7 = 1.0 / 7, c9 = 1.0 / 9, c11 = 1.0 / 11;
  const double r4 = r2 * r2, r8 = r4 * r4;
  const double p = (1.0 - r2 * c3) + r4 * (c5 - r2 * c7) + r8 * (c9 - r2 * c11);
  return kAngleCentre[k] + r * p;
}
}  // namespace detail

inline double fast_atan2(double y, double x) {
  constexpr double kHalfPi = 1.57079632679489661923, kPiValue = 3.14159265358979323846;
  const double ax = std::fabs(x), ay = std::fabs(y);
  if (ax == 0.0 && ay == 0.0) return 0.0;
  const bool swapped = ay > ax;
  const double lo = swapped ? ax : ay, hi = swapped ? ay : ax;
  double a = detail::atan_ratio(lo, hi);
  a = swapped ? kHalfPi - a : a;
  a = x < 0 ? kPiValue - a : a;
  return y < 0 ? -a : a;
}

}  // namespace plumb::windowed
