// Cramer-Rao lower bound of the rotating-platform measurement (docs/conventions.md "Reference
// scenario"): six channels (G and B, tool frame) in white noise sigma_a (each accelerometer axis)
// and sigma_m (each magnetometer axis); unknowns theta = (I, A, T0, rate) with T = T0 + rate t;
// g, B and dip known. J = sum_k H_k^T Sigma^-1 H_k with H_k = dh_k/dtheta; bound = sqrt(diag J^-1).
#pragma once

namespace plumb::windowed {

struct CrbCase {
  double g = 9.80665;
  double total_b = 48.4;        // uT
  double dip_deg = 45.5;
  double inclination_deg = 1;
  double azimuth_deg = 0;
  double toolface0_deg = 0;
  double rpm = 0;
  double sigma_accel = 0.01;    // m/s^2
  double sigma_mag = 0.1;       // uT
  double sample_rate_hz = 100;
  double duration_s = 10;
};

struct CrbResult {
  bool ok = false;              // false when the information matrix is singular
  double inclination_deg = 0;   // one-sigma bounds
  double azimuth_deg = 0;
  double toolface0_deg = 0;
  double rpm = 0;
};

CrbResult cramer_rao_bound(const CrbCase& c);

// Noise standard deviations from SNRs in dB (docs/conventions.md "Noise and signal-to-noise ratio").
double sigma_from_snr(double amplitude, double snr_db);

}  // namespace plumb::windowed
