// Rotation profiles of the platform: the angle is the closed-form integral of the rate, so it is
// exact at any t (no accumulated integration error) and continuous across profile phases.
#include <algorithm>
#include <cmath>

#include "plumb/core/attitude.hpp"
#include "plumb/sim/platform.hpp"

namespace plumb::sim {
namespace {

// Integral of the rate from 0 to t, in revolutions-per-minute times seconds.
double rpm_seconds(const RotationProfile& p, double t) {
  switch (p.kind) {
    case ProfileKind::Constant:
      return p.rpm * t;
    case ProfileKind::Ramp: {
      if (p.ramp_s <= 0) return p.rpm_end * t;
      if (t <= p.ramp_s) return p.rpm * t + 0.5 * (p.rpm_end - p.rpm) * t * t / p.ramp_s;
      return 0.5 * (p.rpm + p.rpm_end) * p.ramp_s + p.rpm_end * (t - p.ramp_s);
    }
    case ProfileKind::StopAndGo: {
      // Turning at twice the mean for the first half of each period keeps the mean speed `rpm`.
      const double half = 0.5 * p.period_s;
      const double periods = std::floor(t / p.period_s);
      const double in_period = t - periods * p.period_s;
      return 2.0 * p.rpm * (periods * half + std::min(in_period, half));
    }
    case ProfileKind::StickSlip: {
      const double w = 2.0 * kPi / p.period_s;
      return p.rpm * (t - std::sin(w * t) / w);
    }
  }
  return 0;
}

}  // namespace

double RotationProfile::angle(double t, double toolface0) const {
  return toolface0 + kRpm * rpm_seconds(*this, t);
}

double RotationProfile::rpm_at(double t) const {
  switch (kind) {
    case ProfileKind::Constant:
      return rpm;
    case ProfileKind::Ramp:
      if (ramp_s <= 0 || t >= ramp_s) return rpm_end;
      return rpm + (rpm_end - rpm) * t / ramp_s;
    case ProfileKind::StopAndGo: {
      const double in_period = t - std::floor(t / period_s) * period_s;
      return in_period < 0.5 * period_s ? 2.0 * rpm : 0.0;
    }
    case ProfileKind::StickSlip:
      return rpm * (1.0 - std::cos(2.0 * kPi * t / period_s));
  }
  return 0;
}

}  // namespace plumb::sim
