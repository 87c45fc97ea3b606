#include "plumb/strapdown/heave_filter.hpp"

#include <algorithm>
#include <cmath>

namespace plumb::strapdown {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kSpeedSd = 0.05;     // m/s, the trend's speed at the start: a rate of penetration
constexpr double kRopSd = 0.02;       // m/s, how far the speed wanders over kSpeedWanderS

double omega_of(int model) {
  return kTwoPi / (HeaveFilter::kShortestPeriodS + HeaveFilter::kPeriodStepS * (model - 1));
}

// A damped oscillator's transition over dt, exact.
Eigen::Matrix2d oscillator(double omega, double dt) {
  const double zw = HeaveFilter::kDamping * omega, wd = omega * std::sqrt(1 - HeaveFilter::kDamping * HeaveFilter::kDamping);
  const double e = std::exp(-zw * dt), c = std::cos(wd * dt), s = std::sin(wd * dt);
  Eigen::Matrix2d osc;
  osc << e * (c + zw / wd * s), e * s / wd, -e * omega * omega / wd * s, e * (c - zw / wd * s);
  return osc;
}

}  // namespace

void HeaveFilter::start(double depth, double depth_sd) {
  const double white = std::max(kMinWhiteSdM, kWhiteShare * depth_sd);
  const double swell_sd = std::sqrt(std::max(0.0, depth_sd * depth_sd - white * white));
  swell_models_awake_ = swell_sd >= kMinSwellSdM;
  for (int i = 0; i <= kModels; ++i) {
    Model& m = models_[static_cast<std::size_t>(i)];
    m = Model{};
    m.x(0) = depth;
    m.p(0, 0) = white * white;
    m.p(1, 1) = kSpeedSd * kSpeedSd;
    if (i > 0) {
      m.p(2, 2) = swell_sd * swell_sd;
      m.p(3, 3) = swell_sd * swell_sd * omega_of(i) * omega_of(i);
    }
  }
  quiet_ = models_[0];
}

// The trend: position and a speed that wanders (a random walk of kRopSd over kSpeedWanderS). The
// swell: a damped oscillator whose transition is exact for the step and whose noise keeps its
// stationary variance, swell_sd^2 and (omega swell_sd)^2 (P_inf - Phi P_inf Phi^T).
void HeaveFilter::predict(Model& m, double dt, int model, double swell_sd) {
  Mat4 phi = Mat4::Identity();
  phi(0, 1) = dt;
  Mat4 q = Mat4::Zero();
  const double qv = kRopSd * kRopSd / kSpeedWanderS;
  q(0, 0) = qv * dt * dt * dt / 3;
  q(0, 1) = q(1, 0) = qv * dt * dt / 2;
  q(1, 1) = qv * dt;
  if (model > 0) {
    // (Reports come at a steady interval: the transitions are computed once for it.)
    if (dt != oscillator_dt_) {
      for (int i = 1; i <= kModels; ++i) oscillators_[static_cast<std::size_t>(i)] = oscillator(omega_of(i), dt);
      oscillator_dt_ = dt;
    }
    const double omega = omega_of(model);
    const Eigen::Matrix2d& osc = oscillators_[static_cast<std::size_t>(model)];
    phi.block<2, 2>(2, 2) = osc;
    const Eigen::Matrix2d p_inf = Eigen::Vector2d(swell_sd * swell_sd, omega * omega * swell_sd * swell_sd).asDiagonal();
    q.block<2, 2>(2, 2) = p_inf - osc * p_inf * osc.transpose();
  }
  m.x = phi * m.x;
  m.p = phi * m.p * phi.transpose() + q;
}

// A scalar update; returns the innovation's log-likelihood.
double HeaveFilter::update(Model& m, double z, const Eigen::Matrix<double, 1, 4>& h, double r) {
  const double innovation = z - h.dot(m.x);
  const Vec4 ph = m.p * h.transpose();
  const double s = h.dot(ph) + r;
  const Vec4 k = ph / s;
  m.x += k * innovation;
  m.p -= k * ph.transpose();
  m.p = 0.5 * (m.p + m.p.transpose());
  return -0.5 * (std::log(kTwoPi * s) + innovation * innovation / s);
}

void HeaveFilter::report(double t, double depth, bool still, double depth_sd) {
  if (!std::isfinite(depth) || !(depth_sd > 0)) return;
  if (!last_t_ || t - *last_t_ > kRestartAfterS || t <= *last_t_) {
    if (!last_t_ || t > *last_t_) start(depth, depth_sd);
    last_t_ = t;
    found_ = false;
    swell_ = 0;
    return;
  }
  const double dt = t - *last_t_;
  if (dt < kReportIntervalS) return;
  last_t_ = t;
  const double white = std::max(kMinWhiteSdM, kWhiteShare * depth_sd);
  const double swell_sd = std::sqrt(std::max(0.0, depth_sd * depth_sd - white * white));
  const double forget = std::exp(-dt / kMemoryS);
  const Eigen::Matrix<double, 1, 4> on_depth(1, 0, 1, 0), on_speed(0, 1, 0, 0);
  // Where the depth's noise leaves no room for a swell (a land rig's centimetre), the swell models
  // would be the no-swell one: they sleep, and wake from it when the noise grows (a swell measured).
  const bool room = swell_sd >= kMinSwellSdM;
  if (room && !swell_models_awake_) {
    for (int i = 1; i <= kModels; ++i) {
      Model& m = models_[static_cast<std::size_t>(i)];
      m = models_[0];
      m.x.tail<2>().setZero();
      m.p.block<2, 4>(2, 0).setZero();
      m.p.block<4, 2>(0, 2).setZero();
      m.p(2, 2) = swell_sd * swell_sd;
      m.p(3, 3) = swell_sd * swell_sd * omega_of(i) * omega_of(i);
    }
  }
  swell_models_awake_ = room;
  const int last = room ? kModels : 0;
  for (int i = 0; i <= last; ++i) {
    Model& m = models_[static_cast<std::size_t>(i)];
    predict(m, dt, i, i > 0 ? swell_sd : 0.0);
    if (still) update(m, 0.0, on_speed, kStillSpeedSd * kStillSpeedSd);
  }
  predict(quiet_, dt, 0, 0.0);
  if (still) update(quiet_, 0.0, on_speed, kStillSpeedSd * kStillSpeedSd);
  // The swell this report carries, from the models before they see it (the reports before it):
  // what is left of the report once it is taken out is the report's own noise and what the
  // prediction is not sure of, independent of each other.
  take_out_predicted_swell(white);
  for (int i = 0; i <= last; ++i) {
    Model& m = models_[static_cast<std::size_t>(i)];
    const double r = i > 0 ? white * white : depth_sd * depth_sd;
    m.log_likelihood = forget * m.log_likelihood + update(m, depth, on_depth, r);
  }
  quiet_.log_likelihood = forget * quiet_.log_likelihood + update(quiet_, depth, on_depth, white * white);
}

void HeaveFilter::take_out_predicted_swell(double white) {
  best_ = 0;
  found_ = false;
  swell_ = 0;
  if (!swell_models_awake_) return;
  for (int i = 1; i <= kModels; ++i)
    if (models_[static_cast<std::size_t>(i)].log_likelihood > models_[static_cast<std::size_t>(best_)].log_likelihood) best_ = i;
  const double no_swell = std::max(models_[0].log_likelihood, quiet_.log_likelihood);
  found_ = best_ > 0 && models_[static_cast<std::size_t>(best_)].log_likelihood - no_swell > kClearMargin;
  if (!found_) return;
  // The swell models' mixture, by their likelihoods (the no-swell model lost the test).
  const double top = models_[static_cast<std::size_t>(best_)].log_likelihood;
  std::array<double, kModels + 1> w{};
  double sum = 0, mean = 0, var = 0;
  for (int i = 1; i <= kModels; ++i) {
    w[static_cast<std::size_t>(i)] = std::exp(models_[static_cast<std::size_t>(i)].log_likelihood - top);
    sum += w[static_cast<std::size_t>(i)];
  }
  for (int i = 1; i <= kModels; ++i) w[static_cast<std::size_t>(i)] /= sum;
  weight_ = w;
  for (int i = 1; i <= kModels; ++i) mean += w[static_cast<std::size_t>(i)] * models_[static_cast<std::size_t>(i)].x(2);
  for (int i = 1; i <= kModels; ++i) {
    const Model& m = models_[static_cast<std::size_t>(i)];
    var += w[static_cast<std::size_t>(i)] * (m.p(2, 2) + (m.x(2) - mean) * (m.x(2) - mean));
  }
  swell_ = mean;
  residual_var_ = white * white + var;
}

double HeaveFilter::swell_at(double t) const {
  if (!found_ || !last_t_ || t <= *last_t_) return swell_;
  double swell = 0;
  for (int i = 1; i <= kModels; ++i) {
    const Model& m = models_[static_cast<std::size_t>(i)];
    swell += weight_[static_cast<std::size_t>(i)] * oscillator(omega_of(i), t - *last_t_).row(0).dot(m.x.tail<2>());
  }
  return swell;
}

std::optional<double> HeaveFilter::depth() const {
  if (!last_t_) return std::nullopt;
  return models_[static_cast<std::size_t>(found_ ? best_ : 0)].x(0);
}

std::optional<double> HeaveFilter::period_s() const {
  if (!found_) return std::nullopt;
  return kShortestPeriodS + kPeriodStepS * (best_ - 1);
}

}  // namespace plumb::strapdown
