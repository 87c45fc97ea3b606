// A drilling plan compiled into phases of constant parameters, with the checks that make every
// phase physically meaningful (continuous speed, inclination inside [0, 180] deg).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "drilling_detail.hpp"
#include "plumb/core/attitude.hpp"
#include "plumb/sim/drilling.hpp"
#include "scenario_checks.hpp"

namespace plumb::sim {
namespace {

constexpr Refusal require_plan{"invalid drilling plan"};

constexpr double kPer30m = kDeg / 30.0;  // deg per 30 m -> rad per m

std::string name_of(std::size_t k, const DrillSegment& s) {
  return "segment " + std::to_string(k + 1) + " (" + (s.kind == SegmentKind::Stop ? "stop" : "drill") + ")";
}

// Duration of a drilling segment including both ramps: the ramps together cover rop * ramp.
double drill_duration(std::size_t k, const DrillSegment& s, double ramp) {
  const std::string name = name_of(k, s);
  require_plan(std::isfinite(s.rop_mps) && s.rop_mps > 0, name + ": rate of penetration must be > 0 m/s");
  require_plan(finite_nonneg(s.length_m) && finite_nonneg(s.duration_s), name + ": length and duration must be >= 0");
  require_plan((s.length_m > 0) != (s.duration_s > 0), name + ": give a length or a duration, not both");
  require_plan(std::isfinite(s.build_deg_per_30m) && std::isfinite(s.turn_deg_per_30m),
          name + ": build and turn rates must be finite");
  require_plan(std::isfinite(s.rpm), name + ": rpm must be finite");
  require_plan(s.mode == SteeringMode::Rotary || s.rpm == 0, name + ": sliding keeps the toolface; rpm needs rotary mode");
  const double duration = s.length_m > 0 ? s.length_m / s.rop_mps + ramp : s.duration_s;
  require_plan(duration >= 2.0 * ramp, name + ": too short for its two " + std::to_string(ramp) +
                                      " s speed ramps (at least rop x ramp metres)");
  return duration;
}

}  // namespace

DrillSegment DrillSegment::drill(double length_m, double rop_mps, double build, double turn) {
  DrillSegment s;
  s.length_m = length_m;
  s.rop_mps = rop_mps;
  s.build_deg_per_30m = build;
  s.turn_deg_per_30m = turn;
  return s;
}

DrillSegment DrillSegment::rotary(double length_m, double rop_mps, double rpm, double build, double turn) {
  DrillSegment s = drill(length_m, rop_mps, build, turn);
  s.mode = SteeringMode::Rotary;
  s.rpm = rpm;
  return s;
}

DrillSegment DrillSegment::stop(double duration_s) {
  DrillSegment s;
  s.kind = SegmentKind::Stop;
  s.duration_s = duration_s;
  return s;
}

DrillingTrajectory::DrillingTrajectory(const DrillingPlan& plan) {
  require_plan(std::isfinite(plan.inclination_deg) && plan.inclination_deg >= 0 && plan.inclination_deg <= 180,
          "start inclination must be within [0, 180] deg");
  require_plan(std::isfinite(plan.azimuth_deg) && std::isfinite(plan.toolface_deg), "start azimuth and toolface must be finite");
  require_plan(finite_nonneg(plan.alignment_s), "alignment time must be >= 0 s");
  require_plan(std::isfinite(plan.ramp_s) && plan.ramp_s > 0, "speed ramp must be > 0 s (speed must stay continuous)");
  require_plan(std::isfinite(plan.stick_slip_rpm) && plan.stick_slip_rpm >= 0 && std::isfinite(plan.stick_slip_period_s) &&
                   plan.stick_slip_period_s > 0,
               "stick-slip must be >= 0 rpm with a period > 0 s");

  Phase cur;
  cur.inc0 = plan.inclination_deg * kDeg;
  cur.azi0 = plan.azimuth_deg * kDeg;
  cur.tf0 = plan.toolface_deg * kDeg;
  if (plan.alignment_s > 0) {
    cur.t1 = plan.alignment_s;
    phases_.push_back(cur);
  }
  for (std::size_t k = 0; k < plan.segments.size(); ++k) {
    const DrillSegment& seg = plan.segments[k];
    Phase ph = cur;  // starts where the previous one ended
    ph.t0 = phases_.empty() ? 0.0 : phases_.back().t1;
    ph.stop_index.reset();
    ph.moving = false;
    ph.rop = ph.ramp = ph.build = ph.turn = ph.spin = 0;
    if (seg.kind == SegmentKind::Stop) {
      require_plan(std::isfinite(seg.duration_s) && seg.duration_s > 0, name_of(k, seg) + ": duration must be > 0 s");
      require_plan(seg.length_m == 0, name_of(k, seg) + ": a stop has no length");
      ph.t1 = ph.t0 + seg.duration_s;
      ph.stop_index = stops_++;
      phases_.push_back(ph);
      continue;
    }
    const double duration = drill_duration(k, seg, plan.ramp_s);
    ph.moving = true;
    ph.t1 = ph.t0 + duration;
    ph.rop = seg.rop_mps;
    ph.ramp = plan.ramp_s;
    ph.build = seg.build_deg_per_30m * kPer30m;
    ph.turn = seg.turn_deg_per_30m * kPer30m;
    ph.spin = seg.mode == SteeringMode::Rotary ? seg.rpm * kRpm / seg.rop_mps : 0.0;
    if (seg.mode == SteeringMode::Rotary && plan.stick_slip_rpm > 0) {
      ph.slip = plan.stick_slip_rpm * kRpm;
      ph.slip_w = 2.0 * kPi / plan.stick_slip_period_s;
    }
    phases_.push_back(ph);
    // The next phase starts from this one's end, evaluated in closed form.
    const double length = ph.rop * (duration - ph.ramp);
    cur = ph;
    cur.s0 = ph.s0 + length;
    cur.inc0 = ph.inc0 + ph.build * length;
    cur.azi0 = ph.azi0 + ph.turn * length;
    cur.tf0 = ph.tf0 + ph.spin * length;
    cur.p0 = ph.p0 + detail::along_hole(ph.inc0, ph.azi0, ph.build, ph.turn, length);
    require_plan(cur.inc0 >= -1e-12 && cur.inc0 <= kPi + 1e-12,
            name_of(k, seg) + ": inclination leaves [0, 180] deg (" + std::to_string(cur.inc0 / kDeg) + " deg at its end)");
    cur.inc0 = std::clamp(cur.inc0, 0.0, kPi);
  }
  require_plan(!phases_.empty(), "the plan is empty (no alignment and no segments)");
}

double DrillingTrajectory::drilled_length_m() const {
  const Phase& last = phases_.back();
  return last.moving ? last.s0 + last.rop * (last.t1 - last.t0 - last.ramp) : last.s0;
}

std::size_t DrillingTrajectory::phase_at(double t) const {
  // The phase with t0 <= t < t1; before the start the first, after the end the last.
  const auto it = std::upper_bound(phases_.begin(), phases_.end(), t, [](double v, const Phase& p) { return v < p.t0; });
  return it == phases_.begin() ? 0 : static_cast<std::size_t>(it - phases_.begin()) - 1;
}

bool DrillingTrajectory::still_at(double t) const {
  if (t >= duration_s() || t < 0) return true;
  return !phases_[phase_at(t)].moving;
}

}  // namespace plumb::sim
