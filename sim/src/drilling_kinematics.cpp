// Closed forms of the drilling trajectory: the raised-cosine speed ramp and the displacement along
// a segment of constant build and turn, so the truth carries no integration error.
#include "drilling_detail.hpp"

#include <cmath>

#include "plumb/core/attitude.hpp"

namespace plumb::sim::detail {
namespace {

// sin(x)/x without the 0/0; the two-term series is exact to 1e-20 below 1e-4.
double sinc(double x) {
  if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;
  return std::sin(x) / x;
}

// Integral over [0, len] of sin(a + k x) and cos(a + k x), written with the half-angle so that
// small k loses no digits: 2/k sin(kL/2) (...)(a + kL/2) = L sinc(kL/2) (...)(a + kL/2).
double integral_sin(double a, double k, double len) { return len * sinc(0.5 * k * len) * std::sin(a + 0.5 * k * len); }
double integral_cos(double a, double k, double len) { return len * sinc(0.5 * k * len) * std::cos(a + 0.5 * k * len); }

}  // namespace

Drive raised_cosine_drive(double tau, double duration, double ramp) {
  Drive d;
  const double w = kPi / ramp;
  if (tau <= 0) return d;
  if (tau >= duration) {
    d.along = duration - ramp;
    return d;
  }
  if (tau < ramp) {
    d.rate = 0.5 * (1.0 - std::cos(w * tau));
    d.rate_dot = 0.5 * w * std::sin(w * tau);
    d.along = 0.5 * tau - 0.5 * std::sin(w * tau) / w;
  } else if (tau <= duration - ramp) {
    d.rate = 1.0;
    d.along = 0.5 * ramp + (tau - ramp);
  } else {
    // Mirror image of the rising ramp, counted back from the end.
    const double u = duration - tau;
    d.rate = 0.5 * (1.0 - std::cos(w * u));
    d.rate_dot = -0.5 * w * std::sin(w * u);
    d.along = (duration - ramp) - (0.5 * u - 0.5 * std::sin(w * u) / w);
  }
  return d;
}

Eigen::Vector3d hole_direction(double inc, double azi) {
  return {std::sin(inc) * std::cos(azi), std::sin(inc) * std::sin(azi), std::cos(inc)};
}

Eigen::Vector3d along_hole(double inc0, double azi0, double build, double turn, double length) {
  // sinI cosA = (sin(I+A) + sin(I-A)) / 2, sinI sinA = (cos(I-A) - cos(I+A)) / 2: each term is a
  // sine or cosine of an angle linear in x.
  const double sum0 = inc0 + azi0, sum_k = build + turn;
  const double diff0 = inc0 - azi0, diff_k = build - turn;
  return {0.5 * (integral_sin(sum0, sum_k, length) + integral_sin(diff0, diff_k, length)),
          0.5 * (integral_cos(diff0, diff_k, length) - integral_cos(sum0, sum_k, length)),
          integral_cos(inc0, build, length)};
}

}  // namespace plumb::sim::detail
