// The platform angle found from the signals themselves: the magnetic toolface M = atan2(-By, Bx)
// turns with the platform (docs/conventions.md). Its noisy per-sample values are unwrapped and
// replaced by the smoothest model the data allow: a polynomial in time of degree 1..3 when its
// residuals are no larger than the measured noise (constant speed, ramps), else a short local
// quadratic smoother (stick-slip). Demodulating against a smooth angle keeps magnetometer noise
// out of the gravity phase.
#pragma once

#include <string>
#include <vector>

#include "plumb/windowed/window.hpp"

namespace plumb::windowed {

struct PlatformAngleOptions {
  double smoothing_s = 0.1;  // half-width of the local smoother when no polynomial fits
  int max_degree = 3;        // highest polynomial degree tried (0: always the local smoother)
};

struct PlatformAngle {
  bool ok = false;
  std::string reason;            // why not ok
  std::vector<double> raw;       // unwrapped per-sample magnetic toolface, rad
  std::vector<double> phase;     // smoothed magnetic toolface per sample, rad (unwrapped)
  double rate_rad_s = 0;         // least-squares slope of the unwrapped toolface
  double turn_rad = 0;           // phase.back() - phase.front()
  double block_span_rad = 0;     // span of half-second block means of the raw toolface
  double motion_rad = 0;         // max(block span, |rate| x duration): how far the platform moved
  double phase_noise_var = 0;    // per-sample variance of the raw toolface, rad^2
  double residual_var = 0;       // of the raw toolface about the chosen model
  // Variance of the model's error at the last sample less its mean error (rad^2): what the
  // toolface at the window end carries beyond the demodulated phase. A least-squares polynomial of
  // degree p over n samples has endpoint leverage (p+1)^2/n; the local quadratic of m points 9/m.
  double end_phase_var = 0;
  int model_degree = 0;          // polynomial degree used; 0 = local smoother
  double radial_field = 0;       // RMS of |(Bx, By)|

  bool uniform_linear = false;    // degree-1 model on evenly spaced samples: phase[k] = phase[0] + k step
  double step = 0;               // rad per sample when uniform_linear

  double rpm() const;
  double revolutions() const;    // |turn| / 2 pi
  // cos and sin of phase[k] for every sample (a rotation recurrence when uniform_linear: the
  // per-sample trigonometry would otherwise dominate the estimator's cost).
  void phasors(std::vector<double>& cos_phase, std::vector<double>& sin_phase) const;
};

PlatformAngle track_platform_angle(const WindowData& w, const PlatformAngleOptions& options = {});

// Local quadratic least-squares smoothing of y over +-half_width neighbours (fewer at the ends).
std::vector<double> smooth_local_quadratic(const std::vector<double>& y, int half_width);

// Per-sample noise variance of a smooth series from its second differences (var(d2) = 6 sigma^2).
double noise_variance_from_second_differences(const std::vector<double>& y);

}  // namespace plumb::windowed
