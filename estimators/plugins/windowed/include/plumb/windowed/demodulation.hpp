// Demodulation against the platform angle phi (rad, per sample). On a platform turning about z the
// radial gravity is Gx + iGy = -g sinI e^{-iT} and the radial field Bx - iBy = r e^{iM}, with
// T = M + alpha (alpha fixed by I, A, dip). Demodulated against phi ~ M both become constants:
//   Gx + iGy = c e^{-i phi} + bg,   Bx - iBy = d e^{+i phi} + bm,
// where bg, bm are constant radial sensor biases, which do not turn with the platform. The least
// squares fit of (c, bg) and (d, bm) over one or more revolutions separates them; over less than
// a revolution the biases are not estimated (they cannot be told apart from c, d).
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

#include "plumb/windowed/window.hpp"

namespace plumb::windowed {

struct Demodulation {
  std::complex<double> gravity;       // c: |c| = g sinI, arg(-c) = phi - T
  std::complex<double> field;         // d: |d| = radial field r, arg(d) = M - phi
  std::complex<double> gravity_bias;  // bg (0 unless estimated)
  std::complex<double> field_bias;    // bm
  bool biases_estimated = false;
  double gravity_residual_var = 0;    // per radial axis, m^2/s^4
  double field_residual_var = 0;      // per radial axis, uT^2
  double mean_gz = 0, mean_bz = 0;    // axial means over the same samples
  double gz_var = 0, bz_var = 0;      // sample variances of the axial channels (their noise)
  // Variance of each component (real, imaginary) of gravity or field per unit residual variance:
  // 1/n, or n/det of the normal equations when the biases are fitted alongside.
  double coefficient_var_factor = 0;
  std::size_t n = 0;
};

// Fits over samples [begin, end). Biases are estimated when asked and the samples span at least
// min_turns revolutions of phi.
Demodulation demodulate(const WindowData& w, const std::vector<double>& phi, std::size_t begin, std::size_t end,
                        bool estimate_biases, double min_turns = 1.0);
// The same with cos(phi), sin(phi) precomputed (see PlatformAngle::phasors).
Demodulation demodulate(const WindowData& w, const std::vector<double>& phi, const std::vector<double>& cos_phi,
                        const std::vector<double>& sin_phi, std::size_t begin, std::size_t end, bool estimate_biases,
                        double min_turns = 1.0);

// The end index of the largest whole number of revolutions of phi counted from `begin`
// (the paper's integration interval); returns w.size() when phi turns less than once.
std::size_t whole_revolutions_end(const std::vector<double>& phi, std::size_t begin, int* revolutions = nullptr);

}  // namespace plumb::windowed
