#include "plumb/windowed/demodulation.hpp"

#include <cmath>

#include "plumb/core/attitude.hpp"

namespace plumb::windowed {

Demodulation demodulate(const WindowData& w, const std::vector<double>& phi, std::size_t begin, std::size_t end,
                        bool estimate_biases, double min_turns) {
  std::vector<double> c(phi.size()), s(phi.size());
  for (std::size_t k = begin; k < end; ++k) c[k] = std::cos(phi[k]), s[k] = std::sin(phi[k]);
  return demodulate(w, phi, c, s, begin, end, estimate_biases, min_turns);
}

Demodulation demodulate(const WindowData& w, const std::vector<double>& phi, const std::vector<double>& cos_phi,
                        const std::vector<double>& sin_phi, std::size_t begin, std::size_t end, bool estimate_biases,
                        double min_turns) {
  using C = std::complex<double>;
  Demodulation out;
  const std::size_t n = end - begin;
  out.n = n;
  if (n == 0) return out;
  // Sums for the normal equations of y = c p + b with p = e^{-i phi} (gravity) and
  // y = d conj(p) + b (field): S = sum p, Yg1 = sum conj(p) yg, Yg0 = sum yg, likewise for the
  // field. Written in real arithmetic: std::complex products call a NaN-checking library routine.
  double s_re = 0, s_im = 0, g1_re = 0, g1_im = 0, g0_re = 0, g0_im = 0;
  double m1_re = 0, m1_im = 0, m0_re = 0, m0_im = 0;
  double gg = 0, mm = 0, gz = 0, bz = 0, gz2 = 0, bz2 = 0;
  for (std::size_t k = begin; k < end; ++k) {
    const double c = cos_phi[k], s = sin_phi[k];
    const double gx = w.gx[k], gy = w.gy[k], bx = w.bx[k], by = w.by[k];
    s_re += c, s_im -= s;
    g1_re += c * gx - s * gy, g1_im += s * gx + c * gy;  // conj(p) yg = (c + is)(gx + i gy)
    g0_re += gx, g0_im += gy;
    m1_re += c * bx - s * by, m1_im -= c * by + s * bx;  // p ym = (c - is)(bx - i by)
    m0_re += bx, m0_im -= by;
    gg += gx * gx + gy * gy;
    mm += bx * bx + by * by;
    gz += w.gz[k];
    bz += w.bz[k];
    gz2 += w.gz[k] * w.gz[k];
    bz2 += w.bz[k] * w.bz[k];
  }
  const C sum_p(s_re, s_im), yg1(g1_re, g1_im), yg0(g0_re, g0_im), ym1(m1_re, m1_im), ym0(m0_re, m0_im);
  const double nn = static_cast<double>(n);
  out.mean_gz = gz / nn;
  out.mean_bz = bz / nn;
  out.gz_var = nn > 1 ? std::max(0.0, gz2 - nn * out.mean_gz * out.mean_gz) / (nn - 1) : 0.0;
  out.bz_var = nn > 1 ? std::max(0.0, bz2 - nn * out.mean_bz * out.mean_bz) / (nn - 1) : 0.0;
  const double turns = std::abs(phi[end - 1] - phi[begin]) / (2 * kPi);
  const double det = nn * nn - std::norm(sum_p);
  out.biases_estimated = estimate_biases && turns >= min_turns && det > 0.25 * nn * nn;
  if (out.biases_estimated) {
    out.gravity = (nn * yg1 - std::conj(sum_p) * yg0) / det;
    out.gravity_bias = (nn * yg0 - sum_p * yg1) / det;
    // The field's basis is conj(p): its sum is conj(S).
    out.field = (nn * ym1 - sum_p * ym0) / det;
    out.field_bias = (nn * ym0 - std::conj(sum_p) * ym1) / det;
    out.coefficient_var_factor = nn / det;
  } else {
    out.coefficient_var_factor = 1 / nn;
    out.gravity = yg1 / nn;
    out.field = ym1 / nn;
  }
  // Residual sum of squares of a least-squares fit: sum |y|^2 - Re(theta^H X^H y).
  const double params = out.biases_estimated ? 2.0 : 1.0;
  const double dof = std::max(1.0, 2 * (nn - params));
  const double ssg = gg - std::real(std::conj(out.gravity) * yg1 + std::conj(out.gravity_bias) * yg0);
  const double ssm = mm - std::real(std::conj(out.field) * ym1 + std::conj(out.field_bias) * ym0);
  out.gravity_residual_var = std::max(0.0, ssg) / dof;
  out.field_residual_var = std::max(0.0, ssm) / dof;
  return out;
}

std::size_t whole_revolutions_end(const std::vector<double>& phi, std::size_t begin, int* revolutions) {
  const std::size_t n = phi.size();
  const int whole = static_cast<int>(std::floor(std::abs(phi.back() - phi[begin]) / (2 * kPi)));
  if (revolutions != nullptr) *revolutions = whole;
  if (whole < 1) return n;
  const double target = 2 * kPi * whole;
  for (std::size_t k = begin + 1; k < n; ++k) {
    if (std::abs(phi[k] - phi[begin]) >= target) {
      // Of the two samples around the end of the last turn keep the closer one as the bound.
      const double before = target - std::abs(phi[k - 1] - phi[begin]);
      const double after = std::abs(phi[k] - phi[begin]) - target;
      return after < before ? k : k - 1;
    }
  }
  return n;
}

}  // namespace plumb::windowed
