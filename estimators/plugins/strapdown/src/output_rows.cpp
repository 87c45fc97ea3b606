#include "plumb/strapdown/output_rows.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include <Eigen/Geometry>

#include "plumb/core/attitude.hpp"
#include "plumb/strapdown/attitude_output.hpp"

namespace plumb::strapdown {

using namespace index;

void OutputRows::reset(const NavigatorConfig& config) {
  config_ = config;
  gap_warning_from_ = gap_warning_until_ = -1;
  next_output_t_ = 0;
  output_started_ = false;
  last_row_t_ = 0;
  row_stats_.clear();
  last_b_valid_ = false;
  smoother_.clear();
  smoother_.consider(config.mag_axial_bias_learnt ? -1 : index::kMagAxial);
  pending_.clear();
}

void OutputRows::add_reading(const InputReading& in) {
  if (in.b) {
    last_b_ = *in.b;
    last_b_valid_ = true;
  }
  row_stats_.add(in.f, in.w, in.b, in.t);
}

std::string OutputRows::fill_attitude(Estimate& e, const NavState& x, const StateMatrix& p,
                                      const RowContext& context) const {
  const Eigen::Matrix3d c_bn = x.q.toRotationMatrix();
  const AttitudeWithSigma a =
      attitude_with_sigma(c_bn, p.block<3, 3>(kAtt, kAtt), std::sin(kMinInclinationForToolfaceDeg * kDeg));
  e.inclination_deg = a.inclination * kRadToDeg;
  e.azimuth_deg = a.azimuth_valid ? wrap_deg_360(a.azimuth * kRadToDeg) : 0.0;
  e.gravity_toolface_deg = a.toolface_valid ? wrap_deg_360(a.toolface * kRadToDeg) : 0.0;
  e.inclination_sd_deg = a.inclination_sd * kRadToDeg;
  e.azimuth_sd_deg = a.azimuth_sd * kRadToDeg;
  // The toolface of a turning tool is known only as well as the instant it stands for (the row's
  // mean rate: e.rpm is filled before): as stated, and as the stamps' own jitter leaves it.
  const double time_tag_sd = std::hypot(config_.time_tag_sd, context.measured_instant_sd_s);
  e.toolface_sd_deg = std::hypot(a.toolface_sd * kRadToDeg, std::abs(e.rpm) * 6.0 * time_tag_sd);
  e.valid = true;
  e.azimuth_valid = a.azimuth_valid;
  e.toolface_valid = a.toolface_valid;
  NavigationState nav;
  for (int k = 0; k < 3; ++k) {
    nav.position_m[k] = x.p[k];
    nav.velocity_mps[k] = x.v[k];
    nav.position_sd_m[k] = std::sqrt(std::max(0.0, p(kPos + k, kPos + k)));
    nav.velocity_sd_mps[k] = std::sqrt(std::max(0.0, p(kVel + k, kVel + k)));
  }
  nav.still = context.still;
  nav.zero_velocity_updates = context.stops;
  nav.azimuth_reference = context.azimuth_reference;
  e.navigation = nav;
  return toolface_from_north(e, c_bn, p.block<3, 3>(kAtt, kAtt), a.inclination, context);
}

// The magnetic toolface from the navigator's attitude and the reference field (the last reading's
// when the magnetometer does not serve azimuth), and near vertical what to steer by: the toolface
// from north, magnetic or (without a magnetometer) gyro, with its sigma.
std::string OutputRows::toolface_from_north(Estimate& e, const Eigen::Matrix3d& c_bn, const Eigen::Matrix3d& p_att,
                                            double inclination, const RowContext& context) const {
  const double min_sin = std::sin(kMinInclinationForToolfaceDeg * kDeg);
  const ReferenceToolface m =
      reference_toolface(c_bn, p_att, context.field_direction_n.value_or(Eigen::Vector3d::UnitX()), min_sin);
  if (context.field_direction_n && m.valid) e.magnetic_toolface_deg = m.toolface * kRadToDeg;
  if (!(inclination < config_.toolface_switch) || !m.valid) return {};
  const double time_tag_sd = std::hypot(config_.time_tag_sd, context.measured_instant_sd_s);
  const double sd_deg = std::hypot(m.sd * kRadToDeg, std::abs(e.rpm) * 6.0 * time_tag_sd);
  if (context.field_direction_n) {
    return format("near vertical (I %.1f deg): steer by the magnetic toolface magnetic_toolface_deg (sigma %.2f deg)",
                  inclination * kRadToDeg, sd_deg);
  }
  return format("near vertical (I %.1f deg): steer by the gyro toolface from north %.2f deg (sigma %.2f deg)",
                inclination * kRadToDeg, m.toolface * kRadToDeg, sd_deg);
}

Estimate OutputRows::row(double t, const RowContext& context, std::size_t& note_at) const {
  note_at = std::string::npos;
  Estimate e;
  e.estimator = "strapdown";
  e.t_start = last_row_t_;
  e.t_end = t;
  e.samples_used = static_cast<std::uint32_t>(row_stats_.count());
  if (row_stats_.count() > 0) {
    const Eigen::Vector3d f = row_stats_.mean_f();
    e.total_g = f.norm();
    // Rotation speed: the tool-axis rate less the earth rate's share (below 0.01 rpm anyway).
    e.rpm = row_stats_.mean_w().z() * 60.0 / (2.0 * std::numbers::pi);
    e.rotating = std::abs(e.rpm) > 1.0;
    if (row_stats_.mag_count() > 0) {
      const Eigen::Vector3d b = row_stats_.mean_b();
      e.total_b = b.norm();
      e.dip_deg = dip_of(f, b) * kRadToDeg;
    }
  }
  if (last_b_valid_) e.magnetic_toolface_deg = wrap_deg_360(std::atan2(-last_b_.y(), last_b_.x()) * kRadToDeg);
  if (context.aligned && context.why.empty()) {
    const std::string note = fill_attitude(e, context.filter->state(), context.filter->covariance(), context);
    std::string warning;
    if (t >= gap_warning_from_ && t <= gap_warning_until_) warning = "time gap bridged by prediction only";
    if (!context.field_warning.empty()) warning += (warning.empty() ? "" : "; ") + context.field_warning;
    if (!context.motion_warning.empty()) warning += (warning.empty() ? "" : "; ") + context.motion_warning;
    if (!context.range_warning.empty()) warning += (warning.empty() ? "" : "; ") + context.range_warning;
    if (context.azimuth_reference == "relative" && !config_.initial_azimuth && !config_.gyrocompass) {
      warning += std::string(warning.empty() ? "" : "; ") + "no magnetometer and no initial_azimuth_deg: azimuth relative to the alignment heading";
    }
    if (!note.empty()) {
      if (!warning.empty()) warning += "; ";
      note_at = warning.size();
      warning += note;
    }
    e.reason = warning;
  } else {
    e.reason = context.why;
    NavigationState nav;
    nav.azimuth_reference = context.azimuth_reference;
    e.navigation = nav;
  }
  for (double* v : {&e.inclination_deg, &e.azimuth_deg, &e.gravity_toolface_deg, &e.magnetic_toolface_deg, &e.rpm,
                    &e.inclination_sd_deg, &e.azimuth_sd_deg, &e.toolface_sd_deg, &e.dip_deg, &e.total_g, &e.total_b}) {
    if (!std::isfinite(*v)) {
      *v = 0;
      e.valid = e.azimuth_valid = e.toolface_valid = false;
      e.reason = "non-finite result";
    }
  }
  return e;
}

bool OutputRows::due(double t) {
  if (!output_started_) {
    output_started_ = true;
    next_output_t_ = t + 1.0 / config_.output_rate_hz;
    last_row_t_ = t;
    return false;
  }
  return t >= next_output_t_ - 1e-9;
}

void OutputRows::emit(double t, const RowContext& context, Counters& counters, std::vector<Estimate>& out) {
  const double period = 1.0 / config_.output_rate_hz;
  std::size_t note_at = std::string::npos;
  Estimate e = row(t, context, note_at);
  count(counters, "rows");
  if (!e.valid) count(counters, "invalid_rows");
  next_output_t_ += period;
  if (next_output_t_ <= t) next_output_t_ = t + period;
  last_row_t_ = t;
  row_stats_.clear();
  if (config_.smooth) {
    PendingRow pr{std::move(e), std::nullopt, note_at};
    if (context.aligned && pr.row.valid && smoother_.size() > 0) pr.epoch = smoother_.size() - 1;
    pending_.push_back(std::move(pr));
  } else {
    out.push_back(std::move(e));
  }
}

void OutputRows::store_epoch(const FilterState& filter, const FilterState::Prediction& prediction) {
  smoother_.store(prediction.phi, prediction.dt, prediction.noise, prediction.extra, filter.correction(),
                  filter.state(), filter.gyro_bias(), filter.accel_bias(), filter.covariance());
}

void OutputRows::store_alignment(const FilterState& filter) {
  smoother_.store(StateMatrix::Identity(), 0.0, ProcessNoise{}, UnseenMotionNoise{}, filter.correction(),
                  filter.state(), filter.gyro_bias(), filter.accel_bias(), filter.covariance());
}

void OutputRows::flush_smoothed(const RowContext& context, std::vector<Estimate>& out) {
  std::vector<std::optional<SmoothedEpoch>> smoothed(smoother_.size());
  std::vector<bool> wanted(smoother_.size(), false);
  for (const PendingRow& pr : pending_) {
    if (pr.epoch) wanted[*pr.epoch] = true;
  }
  smoother_.smooth([&](std::size_t k, const SmoothedEpoch& e) {
    if (wanted[k]) smoothed[k] = e;
  });
  for (PendingRow& pr : pending_) {
    if (pr.epoch && smoothed[*pr.epoch]) {
      const std::string reason = pr.row.reason;
      const bool still = pr.row.navigation ? pr.row.navigation->still : false;
      const std::uint32_t zupts = pr.row.navigation ? pr.row.navigation->zero_velocity_updates : 0;
      const std::string note = fill_attitude(pr.row, smoothed[*pr.epoch]->state, smoothed[*pr.epoch]->p, context);
      pr.row.navigation->still = still;
      pr.row.navigation->zero_velocity_updates = zupts;
      // The forward row's warnings, with the near-vertical note of the smoothed attitude.
      std::string warnings = reason.substr(0, std::min(pr.toolface_note_at, reason.size()));
      if (!note.empty()) {
        if (!warnings.empty() && pr.toolface_note_at == std::string::npos) warnings += "; ";
        warnings += note;
      } else if (pr.toolface_note_at != std::string::npos && warnings.size() >= 2) {
        warnings.resize(warnings.size() - 2);  // the "; " before the note that went
      }
      pr.row.reason = warnings;
    }
    out.push_back(std::move(pr.row));
  }
  pending_.clear();
}

}  // namespace plumb::strapdown
