// Demodulation against a known platform angle: amplitudes, phases and constant biases.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "plumb/core/attitude.hpp"
#include "plumb/windowed/demodulation.hpp"

namespace plumb::windowed {
namespace {

using C = std::complex<double>;

// Gravity c e^{-i phi} + bg and field d e^{i phi} + bm over `turns` revolutions.
WindowData make(C c, C bg, C d, C bm, double turns, std::vector<double>& phi, int n = 1000) {
  WindowData w;
  phi.clear();
  for (int k = 0; k < n; ++k) {
    const double p = 2 * kPi * turns * k / n;
    const C g = c * std::exp(C(0, -p)) + bg, m = d * std::exp(C(0, p)) + bm;
    phi.push_back(p);
    w.t.push_back(k * 0.01);
    w.gx.push_back(g.real()), w.gy.push_back(g.imag()), w.gz.push_back(9.8);
    w.bx.push_back(m.real()), w.by.push_back(-m.imag()), w.bz.push_back(34);
  }
  return w;
}

TEST(Demodulation, SeparatesConstantBiasesOverANonIntegerNumberOfTurns) {
  std::vector<double> phi;
  const C c = std::polar(0.0873, 0.7), bg(0.004, -0.003), d = std::polar(33.9, -0.2), bm(0.07, 0.05);
  const WindowData w = make(c, bg, d, bm, 2.37, phi);
  const Demodulation dm = demodulate(w, phi, 0, w.size(), true);
  ASSERT_TRUE(dm.biases_estimated);
  EXPECT_NEAR(std::abs(dm.gravity - c), 0, 1e-12);
  EXPECT_NEAR(std::abs(dm.gravity_bias - bg), 0, 1e-12);
  EXPECT_NEAR(std::abs(dm.field - d), 0, 1e-10);
  EXPECT_NEAR(std::abs(dm.field_bias - bm), 0, 1e-10);
  EXPECT_NEAR(dm.gravity_residual_var, 0, 1e-20);
  EXPECT_NEAR(dm.mean_gz, 9.8, 1e-12);
}

TEST(Demodulation, WithoutATurnBiasesAreNotEstimated) {
  std::vector<double> phi;
  const WindowData w = make(std::polar(0.1, 0.3), 0, std::polar(30.0, 0.1), 0, 0.3, phi);
  const Demodulation dm = demodulate(w, phi, 0, w.size(), true);
  EXPECT_FALSE(dm.biases_estimated);
  EXPECT_NEAR(std::abs(dm.gravity - std::polar(0.1, 0.3)), 0, 1e-12);
}

TEST(Demodulation, WholeRevolutionsEndCountsTurns) {
  std::vector<double> phi;
  make(0.1, 0, 30.0, 0, 2.5, phi);  // 400 samples per turn
  int turns = 0;
  EXPECT_EQ(whole_revolutions_end(phi, 0, &turns), 800u);
  EXPECT_EQ(turns, 2);
  make(0.1, 0, 30.0, 0, 0.8, phi);
  EXPECT_EQ(whole_revolutions_end(phi, 0, &turns), phi.size());
  EXPECT_EQ(turns, 0);
}

}  // namespace
}  // namespace plumb::windowed
