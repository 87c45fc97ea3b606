// Mechanization and error-model physics against exact solutions.
#include <cmath>
#include <cstdio>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "plumb/strapdown/error_state_filter.hpp"
#include "plumb/strapdown/mechanization.hpp"
#include "plumb/strapdown/rotation.hpp"
#include "strapdown_test_support.hpp"

namespace plumb::strapdown::test {
namespace {

// The filter's algebra checked against the textbook products, written in dynamic-size matrices:
// Eigen's general product is a reference independent of the fixed-size code the filter compiles
// (and compiles once for every size, where fixed-size 25 x 25 products cost seconds each).
using Dynamic = Eigen::MatrixXd;
Dynamic mul(const Dynamic& a, const Dynamic& b) { return a * b; }
Dynamic transposed(const Dynamic& a) { return a.transpose(); }
Dynamic textbook_sandwich(const Dynamic& phi, const Dynamic& m) { return mul(mul(phi, m), transposed(phi)); }
Dynamic textbook_gain(const Dynamic& p, const Dynamic& h, const Dynamic& r) {
  const Dynamic pht = mul(p, transposed(h));
  const Dynamic s = mul(h, pht) + r;
  return mul(pht, s.inverse());
}
// (I-KH) P (I-KH)' + K R K'.
Dynamic textbook_joseph(const Dynamic& p, const Dynamic& h, const Dynamic& r) {
  const Dynamic k = textbook_gain(p, h, r);
  const Dynamic ikh = Dynamic::Identity(p.rows(), p.cols()) - mul(k, h);
  return textbook_sandwich(ikh, p) + textbook_sandwich(k, r);
}
StateMatrix random_covariance() {
  const Dynamic a = Dynamic::Random(kStates, kStates);
  return mul(a, transposed(a)) + Dynamic::Identity(kStates, kStates);
}

// A constant rate about a fixed axis with no earth rate: the exact attitude is exp(t [w x]).
// At 10 Hz and 120 rpm a step turns 1.26 rad; the sub-stepped Runge-Kutta must still be exact to
// the truncation bound (angle/2)^5/120 per sub-step, and uneven steps change nothing.
// A force fixed in the navigation frame, read by a tool turning at w about an axis tilted from it:
// its mean over an interval (numerically, a thousand points) is what instant_to_mean makes of its
// value at the middle, and mean_to_instant takes that back. A turn of a radian per interval (10 Hz
// at 95 rpm) shortens the part across the axis by 4 %.
TEST(MechanizationPhysics, MeansOfATurningForceBothWays) {
  const Eigen::Vector3d w(0.02, -0.03, 10.0);  // rad/s
  const double dt = 0.1;
  const Eigen::Vector3d f_mid(3.0, -1.5, -8.9);
  const Eigen::Vector3d u = w.normalized();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  constexpr int kPoints = 1000;
  for (int k = 0; k < kPoints; ++k) {
    const double s = ((k + 0.5) / kPoints - 0.5) * dt;
    // Seen from the tool, a vector fixed outside turns the other way.
    mean += Eigen::AngleAxisd(-w.norm() * s, u) * f_mid / kPoints;
  }
  const Eigen::Vector3d made = instant_to_mean(f_mid, w, dt);
  EXPECT_LT((made - mean).norm(), 1e-5 * f_mid.norm());
  EXPECT_LT((mean_to_instant(made, w, dt) - f_mid).norm(), 1e-12 * f_mid.norm());
  const Eigen::Vector3d across = f_mid - u * u.dot(f_mid);
  const double half = 0.5 * w.norm() * dt;
  EXPECT_NEAR((made - u * u.dot(made)).norm() / across.norm(), std::sin(half) / half, 1e-12);
}

TEST(Mechanization, ConstantRotationMatchesExactSolution) {
  const Eigen::Vector3d w = Eigen::Vector3d(0.3, -0.2, 1.0).normalized() * (120.0 * 2 * kPi / 60.0);
  Mechanization mech(Eigen::Vector3d::Zero(), 9.8);
  for (const double rate : {10.0, 100.0}) {
    NavState x;
    double t = 0;
    int k = 0;
    while (t < 60.0) {
      const double dt = (k++ % 3 == 0 ? 1.5 : 0.75) / rate;  // uneven steps
      const ImuReading a{t, Eigen::Vector3d(0, 0, -9.8), w};
      const ImuReading b{t + dt, Eigen::Vector3d(0, 0, -9.8), w};
      mech.step(x, a, b);
      t += dt;
    }
    const Eigen::Quaterniond exact = quaternion_from_rotation_vector(w * t);
    const double err = Eigen::AngleAxisd(x.q * exact.inverse()).angle();
    // RK4 on q' = q (0, w)/2 keeps exp(i x), x = half the sub-step angle, to x^4: the phase error is
    // x^5/120 per sub-step, twice that in rotation angle. At most kMaxSubstepAngle per sub-step.
    const double x_max = Mechanization::kMaxSubstepAngle / 2;
    const double substeps = w.norm() * t / Mechanization::kMaxSubstepAngle + 3.0 * t * rate;
    const double bound = substeps * 2.0 * std::pow(x_max, 5) / 120.0;
    EXPECT_LT(err, bound) << "rate " << rate << " Hz";
    std::printf("constant rotation, %.0f Hz, %.0f rad turned: error %.2e rad (bound %.2e)\n", rate, w.norm() * t, err, bound);
    EXPECT_NEAR(x.q.norm(), 1.0, 1e-12);
  }
}

// A rotation that speeds up about a fixed axis, w(t) = w' t (a rotary start): the exact angle is
// w' t^2 / 2. Instantaneous samples joined by straight lines lose dt^2 w'' / 12 per unit time of
// the rate's curvature; here the rate is linear, so both interpolations are exact up to Runge-Kutta
// truncation, and for a curved rate (w = c t^2) the parabola keeps the error at round-off level
// while a line would leave dt^2 c / 6 per second.
TEST(Mechanization, AcceleratingRotationMatchesExactSolution) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.1, 0.2, 1.0).normalized();
  const double c = 0.05;  // rad/s^3: w = c t^2, angle = c t^3 / 3
  Mechanization mech(Eigen::Vector3d::Zero(), 9.8);
  const double rate = 10, t_end = 10;
  NavState x;
  std::vector<ImuReading> r;
  for (int k = 0; k <= static_cast<int>(t_end * rate); ++k) {
    const double t = k / rate;
    r.push_back({t, Eigen::Vector3d(0, 0, -9.8), axis * c * t * t});
  }
  for (std::size_t k = 1; k < r.size(); ++k) mech.step(x, r[k - 1], r[k], nullptr, k >= 2 ? &r[k - 2] : nullptr);
  const Eigen::Quaterniond exact = quaternion_from_rotation_vector(axis * c * t_end * t_end * t_end / 3.0);
  const double err = Eigen::AngleAxisd(x.q * exact.inverse()).angle();
  const double linear_error = c / 6.0 * t_end / (rate * rate);  // what straight lines would leave
  std::printf("accelerating rotation at 10 Hz: error %.2e rad (straight lines: %.2e)\n", err, linear_error);
  // Only the first step, which has no earlier reading, is a straight line: it leaves c dt^3 / 6.
  const double first_step = c / (6.0 * rate * rate * rate);
  EXPECT_LT(err, 1.05 * first_step);
  EXPECT_LT(err, 0.02 * linear_error);
}

// A still tool whose gyros see exactly the earth rate keeps its attitude for an hour, and its
// velocity stays at zero (gravity and the accelerometers cancel).
TEST(Mechanization, StillToolOnRotatingEarthKeepsAttitude) {
  StillTool tool;
  tool.rate_hz = 50;
  tool.duration_s = 3600;
  tool.magnetometer = false;
  const auto samples = tool.samples();
  Mechanization mech(earth_rate_ned(tool.latitude_deg * kDeg), tool.g);
  NavState x;
  x.q = Eigen::Quaterniond(tool.c_nb().transpose());
  for (std::size_t k = 1; k < samples.size(); ++k) {
    mech.step(x, {samples[k - 1].t, samples[k - 1].f, samples[k - 1].w}, {samples[k].t, samples[k].f, samples[k].w});
  }
  EXPECT_LT(attitude_error(x.q, tool.c_nb()).norm(), 1e-9);
  EXPECT_LT(x.v.norm(), 1e-6);
}

// Without updates, a constant gyro bias b turns the attitude at C b: after t the error is
// |b| t (the earth rate's coupling -w_ie x phi adds a relative (Omega t)^2 / 2 = 1e-3 over 10 min).
TEST(Mechanization, DriftFollowsGyroBias) {
  StillTool tool;
  tool.rate_hz = 100;
  tool.duration_s = 600;
  tool.magnetometer = false;
  tool.gyro_bias = Eigen::Vector3d(1.0, -2.0, 0.5) * kDeg / 3600.0;  // deg/h
  const auto samples = tool.samples();
  Mechanization mech(earth_rate_ned(tool.latitude_deg * kDeg), tool.g);
  NavState x;
  x.q = Eigen::Quaterniond(tool.c_nb().transpose());
  for (std::size_t k = 1; k < samples.size(); ++k) {
    mech.step(x, {samples[k - 1].t, samples[k - 1].f, samples[k - 1].w}, {samples[k].t, samples[k].f, samples[k].w});
  }
  const double t = samples.back().t;
  const Eigen::Vector3d predicted = tool.c_nb().transpose() * tool.gyro_bias * t;
  const Eigen::Vector3d actual = attitude_error(x.q, tool.c_nb());
  EXPECT_LT((actual - predicted).norm(), 0.01 * predicted.norm());
}

// The filter's model of the same: with no measurement the attitude variance grows as
// sigma_b^2 t^2 + ARW^2 t (per axis, bias on every axis), which the transition must reproduce.
TEST(ErrorStateFilter, AttitudeVarianceGrowsAsGyroModelSays) {
  const double sigma_b = 1.0 * kDeg / 3600.0, arw = 0.05 * kDeg / 60.0;
  StateMatrix p0 = StateMatrix::Zero();
  p0.block<3, 3>(index::kGyroBias, index::kGyroBias).diagonal().setConstant(sigma_b * sigma_b);
  ErrorStateFilter kf;
  kf.reset(p0);
  ProcessNoise noise;
  noise.gyro_arw = arw;
  StepIntegrals step;
  const double dt = 0.05;
  const Eigen::Matrix3d c = c_nb(1.0, 0.5, 0.2).transpose();
  const double t_end = 600;
  for (double t = 0; t < t_end - 1e-9; t += dt) {
    step.clear();
    step.dt = dt;
    step.c_bn = c * dt;
    step.f_n = Eigen::Vector3d(0, 0, -9.8) * dt;
    const StateMatrix phi = ErrorStateFilter::transition(step, Eigen::Vector3d::Zero());
    kf.predict(phi, dt, noise);
  }
  const double expected = sigma_b * sigma_b * t_end * t_end + arw * arw * t_end;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(kf.covariance()(i, i), expected, 0.01 * expected);
}

// The structured products of the filter equal the plain ones they replace: the transition
// written block by block is I + F dt + (F dt)^2 / 2; its bias rows are the identity's and most of
// its blocks zero, so phi M phi' takes only the non-zero blocks; the multiplied-out Joseph form
// equals (I-KH) P (I-KH)' + K R K'.
TEST(ErrorStateFilterAlgebra, StructuredProductsEqualThePlainOnes) {
  StepIntegrals step;
  step.dt = 0.05;
  step.c_bn = c_nb(0.3, 1.2, -0.7).transpose() * step.dt;
  step.f_n = Eigen::Vector3d(1.1, -0.4, -9.7) * step.dt;
  step.axis_n = Eigen::Vector3d(0.2, 0.3, 0.93) * step.dt;
  step.axis_cross_v = Eigen::Vector3d(0.01, -0.02, 0.005) * step.dt;
  const Eigen::Vector3d w_ie(5e-5, 0, -5e-5);
  const StateMatrix phi = ErrorStateFilter::transition(step, w_ie);
  // The block-by-block transition (gravity's column included) is the plain second-order series of F dt.
  const StateMatrix fdt = ErrorStateFilter::dynamics(step, w_ie) * step.dt;
  const Dynamic fdt_d = fdt;
  const Dynamic series = Dynamic::Identity(kStates, kStates) + fdt_d + 0.5 * mul(fdt_d, fdt_d);
  EXPECT_LT((phi - series).norm(), 1e-14 * series.norm());
  const StateMatrix p = random_covariance();
  const Dynamic plain = textbook_sandwich(phi, p);
  EXPECT_LT((ErrorStateFilter::sandwich(phi, p) - plain).norm(), 1e-12 * plain.norm());

  ProcessNoise noise;
  noise.gyro_arw = 1e-4;
  noise.accel_vrw = 2e-3;
  noise.gyro_bias_walk = 1e-6;
  noise.accel_bias_walk = 1e-5;
  // The trapezoidal process noise written out: (phi Q phi' + Q) / 2, Q the white noises over dt.
  StateVector q = StateVector::Zero();
  q.segment<3>(0).setConstant(noise.gyro_arw * noise.gyro_arw * step.dt);
  q.segment<3>(3).setConstant(noise.accel_vrw * noise.accel_vrw * step.dt);
  q.segment<3>(9).setConstant(noise.gyro_bias_walk * noise.gyro_bias_walk * step.dt);
  q.segment<3>(12).setConstant(noise.accel_bias_walk * noise.accel_bias_walk * step.dt);
  const Dynamic big_q = q.asDiagonal();
  const Dynamic predicted = plain + 0.5 * (textbook_sandwich(phi, big_q) + big_q);
  EXPECT_LT((ErrorStateFilter::predicted_covariance(phi, p, step.dt, noise) - predicted).norm(), 1e-12 * predicted.norm());

  ErrorStateFilter kf;
  kf.reset(p);
  const Eigen::Matrix<double, 3, kStates> h = Eigen::Matrix<double, 3, kStates>::Random();
  const Eigen::Matrix3d r = Eigen::Vector3d(0.1, 0.2, 0.3).asDiagonal();
  const Dynamic joseph = textbook_joseph(p, h, r);
  kf.update<3>(Eigen::Vector3d(0.1, -0.2, 0.3), h, r);
  EXPECT_LT((kf.covariance() - joseph).norm(), 1e-10 * joseph.norm());
}

// The in-place prediction (phi's moved rows only, over their non-zero entries) and the update over
// H's non-zero columns equal the plain products, with every column of phi in use (a turning tool:
// lever arm, spin and g-sensitivity) and with the lever arm's columns zero (a tool that does not turn).
TEST(ErrorStateFilterAlgebra, SparsePredictionAndUpdateEqualThePlainOnes) {
  const StateMatrix p = random_covariance();
  ProcessNoise noise;
  noise.gyro_arw = 1e-4;
  noise.accel_vrw = 2e-3;
  noise.gyro_bias_walk = 1e-6;
  noise.accel_bias_walk = 1e-5;
  for (const bool turning : {true, false}) {
    StepIntegrals step;
    step.dt = 0.05;
    step.c_bn = c_nb(0.3, 1.2, -0.7).transpose() * step.dt;
    step.f_n = Eigen::Vector3d(1.1, -0.4, -9.7) * step.dt;
    step.axis_n = Eigen::Vector3d(0.2, 0.3, 0.93) * step.dt;
    step.axis_cross_v = Eigen::Vector3d(0.01, -0.02, 0.005) * step.dt;
    step.spin_frame = c_nb(0.1, 0.2, 0.3).transpose() * (3.0 * step.dt);
    step.c_gyro_g = Eigen::Matrix<double, 3, 2>::Random() * step.dt;
    if (turning) step.c_lever = Eigen::Matrix<double, 3, 2>::Random() * step.dt;
    const StateMatrix phi = ErrorStateFilter::transition(step, Eigen::Vector3d(5e-5, 0, -5e-5));
    if (!turning) {
      EXPECT_TRUE((phi.block<9, 2>(0, index::kLever).isZero(0.0)));  // the columns skipped
    }
    ErrorStateFilter kf;
    kf.reset(p);
    kf.predict(phi, step.dt, noise);
    const StateMatrix plain = ErrorStateFilter::predicted_covariance(phi, p, step.dt, noise);
    const StateMatrix expected = 0.5 * (plain + plain.transpose());
    EXPECT_LT((kf.covariance() - expected).norm(), 1e-13 * expected.norm()) << (turning ? "turning" : "not turning");
    EXPECT_EQ(kf.covariance(), kf.covariance().transpose());
  }
  // A velocity-only H (zero velocity) and one on attitude and velocity (lateral velocity).
  Eigen::Matrix<double, 2, kStates> h = Eigen::Matrix<double, 2, kStates>::Zero();
  h.block<2, 6>(0, index::kAtt) = Eigen::Matrix<double, 2, 6>::Random();
  const Eigen::Matrix2d r = Eigen::Vector2d(0.1, 0.2).asDiagonal();
  const Dynamic k = textbook_gain(p, h, r);
  const Dynamic joseph = textbook_joseph(p, h, r);
  ErrorStateFilter kf;
  kf.reset(p);
  const Eigen::Vector2d residual(0.1, -0.2);
  const StateVector dx = kf.update<2>(residual, h, r);
  EXPECT_LT((kf.covariance() - joseph).norm(), 1e-12 * joseph.norm());
  const Dynamic dx_expected = mul(k, residual);
  EXPECT_LT((Dynamic(dx) - dx_expected).norm(), 1e-12 * dx_expected.norm());
  EXPECT_EQ(kf.covariance(), kf.covariance().transpose());
  Eigen::Matrix<double, 3, kStates> hv = Eigen::Matrix<double, 3, kStates>::Zero();
  hv.block<3, 3>(0, index::kVel).setIdentity();
  const Eigen::Matrix3d rv = Eigen::Matrix3d::Identity() * 1e-4;
  const Dynamic josephv = textbook_joseph(p, hv, rv);
  kf.reset(p);
  kf.update<3>(Eigen::Vector3d(0.01, 0.02, -0.01), hv, rv);
  EXPECT_LT((kf.covariance() - josephv).norm(), 1e-12 * josephv.norm());
}

}  // namespace
}  // namespace plumb::strapdown::test
